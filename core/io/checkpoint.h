/* Checkpoints of long runs (bin/render --checkpoint, --resume): the whole state of a run, so that a
 * resumed run ends bit-identical to one never stopped.
 *
 * A checkpoint is a byte payload the renderers fill (struct ckpt_buf) inside a file that says what
 * it belongs to: the build that wrote it (a hash of the running executable: the same numbers need
 * the same machine code), the scene (a hash of the loaded data, so changed meshes or textures
 * count), and the options as a canonical text the tool composes. Any of them differing refuses the
 * resume with one line naming which. A trailing checksum over everything detects a truncated or
 * corrupted file before a byte of it is used. Files are written to a temporary beside the target,
 * fsync'ed, renamed into place and the directory fsync'ed: a crash leaves the old checkpoint or
 * the new one, never a mixture.
 *
 * Payloads are raw struct bytes: a checkpoint is only ever read by the build that wrote it. The
 * one thing that does not survive a restart is a pointer; path vertices go through
 * ckpt_put_vertices (path/path_checkpoint.h), which stores their BSDF as an index. The scene's
 * identity is scene/scene_hash.h's. */
#ifndef CHECKPOINT_H
#define CHECKPOINT_H

#include "io/image.h"
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>

struct ckpt_buf {
    unsigned char *p;
    size_t len, cap, pos; /* pos: the read cursor */
    bool short_read;      /* a read ran past the end (a payload of another layout) */
};
void ckpt_buf_free(struct ckpt_buf *b);
void ckpt_put(struct ckpt_buf *b, const void *p, size_t n);
/* Reads n bytes at the cursor; past the end it zero-fills, sets short_read and returns false. */
bool ckpt_get(struct ckpt_buf *b, void *p, size_t n);
#define CKPT_PUT(b, x) ckpt_put((b), &(x), sizeof(x))
#define CKPT_GET(b, x) ckpt_get((b), &(x), sizeof(x))
/* A nested buffer, length first: each thread's state is one, so readers can find them all. */
void ckpt_put_buf(struct ckpt_buf *b, const struct ckpt_buf *inner);
bool ckpt_get_buf(struct ckpt_buf *b, struct ckpt_buf *inner); /* inner borrows b's bytes */
void ckpt_put_image(struct ckpt_buf *b, const struct image *im);
bool ckpt_get_image(struct ckpt_buf *b, struct image *im); /* same size as written, else false */

/* What a checkpoint belongs to. */
struct ckpt_id {
    uint64_t build, scene;
    const char *options; /* canonical text of every option that changes the numbers */
};
/* The running executable's hash (0 if it cannot be read: then no checkpoint is accepted). */
uint64_t ckpt_build_hash(void);
uint64_t hash64(uint64_t h, const void *p, size_t n);

bool ckpt_write_file(const char *path, const struct ckpt_id *id, const struct ckpt_buf *payload, char *err,
                     size_t errlen);
/* Fills payload (owned; free with ckpt_buf_free) or writes one line: unreadable, corrupted or
 * truncated, or written by another build, for another scene or with other options. */
bool ckpt_read_file(const char *path, const struct ckpt_id *id, struct ckpt_buf *payload, char *err, size_t errlen);
/* Whether the file is a whole checkpoint (magic and checksum), whoever wrote it: what a killed
 * run must always leave behind. */
bool ckpt_file_intact(const char *path);
/* Removes the temporaries of checkpoint `path` that processes no longer running left (a kill inside
 * a write leaves one); once per process, and before the first write in any case. */
void ckpt_remove_stale_temporaries(const char *path);

/* How a renderer checkpoints: where to, how often, and what to continue from. */
struct ckpt_ctl {
    const char *path; /* written every `every` seconds and at an interruption */
    double every;     /* <= 0: only at an interruption */
    struct ckpt_id id;
    struct ckpt_buf *resume; /* payload of the run to continue, or NULL */
    bool written;            /* out: a checkpoint was written */
    char err[512];           /* out: why a write failed (the run stops) */
};

/* The rendezvous of a run's threads for a periodic checkpoint. Threads poll; once one finds the
 * time has come, each stores its state in its slot at its next poll and waits; a thread that ends
 * its work stores its final state and leaves. When every slot holds the state of the same moment
 * the last one in calls save(ctx), alone, and all go on. Threads never wait for each other
 * otherwise, so each thread's work is what it would have been without checkpoints. */
struct ckpt_sync {
    pthread_mutex_t lock;
    pthread_cond_t wake;
    int threads, arrived, finished;
    unsigned generation;
    atomic_bool due;
    double every;
    _Atomic double next;
    struct ckpt_buf *slot;
    void (*save)(void *ctx);
    void *ctx;
};
void ckpt_sync_init(struct ckpt_sync *s, int threads, double every, void (*save)(void *ctx), void *ctx);
void ckpt_sync_destroy(struct ckpt_sync *s);
/* Cheap; true when thread tid must store its state in slot[tid] and call ckpt_sync_arrive. */
bool ckpt_sync_poll(struct ckpt_sync *s);
void ckpt_sync_arrive(struct ckpt_sync *s);
/* Called once by each thread when its work ends, after storing its final state. */
void ckpt_sync_finish(struct ckpt_sync *s);

/* A run's checkpoint: the renderer's own header (freed here), then every thread's slot. A write
 * that fails leaves its one-line reason in ctl->err (kept by later successes) and stops the run as
 * Ctrl-C does (interrupt_request); the tool then ends with that line and status 1. */
void ckpt_save_run(struct ckpt_ctl *ctl, struct ckpt_buf *head, const struct ckpt_sync *s);
/* The counterpart, after the renderer has read its header from b: one buffer per thread (borrowing
 * b's bytes; free the array), or NULL when the payload does not end with exactly that many. */
struct ckpt_buf *ckpt_resume_threads(struct ckpt_buf *b, int threads);

#endif
