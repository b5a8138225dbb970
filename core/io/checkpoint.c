/* Checkpoint payloads and files; see checkpoint.h. */
#include "io/checkpoint.h"
#include "base/util.h"
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

void ckpt_buf_free(struct ckpt_buf *b)
{
    free(b->p);
    memset(b, 0, sizeof *b);
}

void ckpt_put(struct ckpt_buf *b, const void *p, size_t n)
{
    if (!n) return; /* an empty buffer has no memory yet, and NULL + 0 is undefined */
    if (b->len + n > b->cap) {
        b->cap = 2 * (b->len + n) + 4096;
        b->p = xrealloc(b->p, b->cap);
    }
    memcpy(b->p + b->len, p, n);
    b->len += n;
}

bool ckpt_get(struct ckpt_buf *b, void *p, size_t n)
{
    if (b->short_read || n > b->len - b->pos) {
        memset(p, 0, n);
        b->short_read = true;
        return false;
    }
    if (!n) return true;
    memcpy(p, b->p + b->pos, n);
    b->pos += n;
    return true;
}

void ckpt_put_buf(struct ckpt_buf *b, const struct ckpt_buf *inner)
{
    uint64_t n = inner->len;
    CKPT_PUT(b, n);
    ckpt_put(b, inner->p, inner->len);
}

bool ckpt_get_buf(struct ckpt_buf *b, struct ckpt_buf *inner)
{
    uint64_t n = 0;
    memset(inner, 0, sizeof *inner);
    if (!CKPT_GET(b, n) || n > b->len - b->pos) {
        b->short_read = inner->short_read = true;
        return false;
    }
    inner->p = b->p + b->pos;
    inner->len = inner->cap = (size_t)n;
    b->pos += (size_t)n;
    return true;
}

void ckpt_put_image(struct ckpt_buf *b, const struct image *im)
{
    CKPT_PUT(b, im->w);
    CKPT_PUT(b, im->h);
    ckpt_put(b, im->px, 3 * sizeof(double) * (size_t)im->w * (size_t)im->h);
}

bool ckpt_get_image(struct ckpt_buf *b, struct image *im)
{
    int w = 0, h = 0;
    CKPT_GET(b, w);
    CKPT_GET(b, h);
    if (w != im->w || h != im->h) {
        b->short_read = true;
        return false;
    }
    return ckpt_get(b, im->px, 3 * sizeof(double) * (size_t)w * (size_t)h);
}

/* Word-wise multiply-xorshift: every step is a bijection of the state for a given word, so a file
 * that differs from the written one in any single word always fails the check. */
uint64_t hash64(uint64_t h, const void *p, size_t n)
{
    const unsigned char *c = p;
    for (; n >= 8; n -= 8, c += 8) {
        uint64_t w;
        memcpy(&w, c, 8);
        h = (h ^ w) * 0x9E3779B97F4A7C15ULL;
        h ^= h >> 29;
    }
    uint64_t w = n;          /* the tail, with its length, so "ab" and "ab\0" differ */
    if (n) memcpy(&w, c, n); /* an empty payload has no buffer at all */
    h = (h ^ w ^ ((uint64_t)n << 56)) * 0xBF58476D1CE4E5B9ULL;
    return h ^ (h >> 31);
}

uint64_t ckpt_build_hash(void)
{
    static uint64_t cached;
    if (cached) return cached;
    FILE *f = fopen("/proc/self/exe", "rb");
    if (!f) return 0;
    uint64_t h = 0x243F6A8885A308D3ULL;
    unsigned char buf[1 << 16];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0)
        h = hash64(h, buf, n);
    bool ok = !ferror(f);
    fclose(f);
    return cached = ok ? h : 0;
}

#define MAGIC "PSSCKPT1"

/* Layout: magic, build, scene, options length and text, payload length (the header), then the
 * payload, then hash64 of the payload seeded with hash64 of the header: the payload, every
 * framebuffer of the run, is hashed where it lies rather than copied behind the header. */
#define HEAD_FIXED (8 + 3 * 8 + 8) /* the header without the options text */

/* The temporaries of this checkpoint (atomic_write's ".tmpPID-NAME" beside it) that processes no
 * longer running left behind: a run killed in a write leaves one, and a resumed run killed again
 * would pile them up. Once per process, before its first write. */
void ckpt_remove_stale_temporaries(const char *path)
{
    static bool done;
    if (done) return;
    done = true;
    const char *slash = strrchr(path, '/'), *base = slash ? slash + 1 : path;
    char dir[4096];
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path) + 1 : 1, slash ? path : ".");
    DIR *d = opendir(dir);
    if (!d) return;
    size_t bl = strlen(base);
    for (struct dirent *e; (e = readdir(d));) {
        char *end;
        long pid = strncmp(e->d_name, ".tmp", 4) ? 0 : strtol(e->d_name + 4, &end, 10);
        if (pid <= 0 || *end != '-' || strcmp(end + 1, base) || strlen(end + 1) != bl) continue;
        if (kill((pid_t)pid, 0) == 0 || errno != ESRCH) continue; /* alive, or not ours to judge */
        char p[8192];
        snprintf(p, sizeof p, "%s%s%s", dir, slash ? "" : "/", e->d_name);
        unlink(p);
    }
    closedir(d);
}

static uint64_t checksum(const unsigned char *head, size_t hlen, const unsigned char *payload, size_t plen)
{
    return hash64(hash64(0, head, hlen), payload, plen);
}

static bool write_parts(const char *tmp, void *parts, char *err, size_t errlen)
{
    return write_chunks(tmp, parts, 4, err, errlen);
}

bool ckpt_write_file(const char *path, const struct ckpt_id *id, const struct ckpt_buf *payload, char *err,
                     size_t errlen)
{
    struct ckpt_buf head = {0};
    ckpt_put(&head, MAGIC, 8);
    CKPT_PUT(&head, id->build);
    CKPT_PUT(&head, id->scene);
    uint64_t olen = strlen(id->options), plen = payload->len;
    CKPT_PUT(&head, olen);
    ckpt_put(&head, id->options, olen);
    CKPT_PUT(&head, plen);
    uint64_t sum = checksum(head.p, head.len, payload->p, payload->len);
    /* four parts, the payload in two halves: tests pause a write between them (util.h) */
    size_t half = payload->len / 2;
    const unsigned char *second = payload->len ? payload->p + half : payload->p; /* an empty payload has no buffer */
    struct chunk parts[4] = {{head.p, head.len}, {payload->p, half}, {second, payload->len - half}, {&sum, sizeof sum}};
    ckpt_remove_stale_temporaries(path);
    bool ok = atomic_write(path, write_parts, parts, err, errlen);
    ckpt_buf_free(&head);
    return ok;
}

/* The whole file in *all, its checksum verified and cut off; or one line in err. */
static bool read_verified(const char *path, struct ckpt_buf *all, char *err, size_t errlen)
{
    memset(all, 0, sizeof *all);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: cannot read the checkpoint", path);
        return false;
    }
    unsigned char buf[1 << 16];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0)
        ckpt_put(all, buf, n);
    fclose(f);
    uint64_t olen = 0, sum = 0;
    if (all->len < HEAD_FIXED + 8 || memcmp(all->p, MAGIC, 8)) {
        snprintf(err, errlen, "%s: not a checkpoint of this harness", path);
        ckpt_buf_free(all);
        return false;
    }
    memcpy(&sum, all->p + all->len - 8, 8);
    memcpy(&olen, all->p + HEAD_FIXED - 16, 8);
    size_t hlen = olen <= all->len - HEAD_FIXED - 8 ? HEAD_FIXED + (size_t)olen : 0;
    if (!hlen || checksum(all->p, hlen, all->p + hlen, all->len - 8 - hlen) != sum) {
        snprintf(err, errlen, "%s: the checkpoint is truncated or corrupted (checksum mismatch); nothing was read",
                 path);
        ckpt_buf_free(all);
        return false;
    }
    all->len -= 8;
    return true;
}

bool ckpt_file_intact(const char *path)
{
    struct ckpt_buf all;
    char err[16];
    bool ok = read_verified(path, &all, err, sizeof err);
    ckpt_buf_free(&all);
    return ok;
}

/* "threads=2 (this run: threads=1)" for the first option word that differs, so that the refusal
 * says which option rather than printing two long lines to compare by eye. */
static void first_difference(const char *was, const char *now, char *out, size_t n)
{
    while (*was || *now) {
        size_t a = strcspn(was, " "), b = strcspn(now, " ");
        if (a != b || memcmp(was, now, a)) {
            snprintf(out, n, "%.*s (this run: %.*s)", (int)a, was, (int)b, now);
            return;
        }
        was += a + (was[a] == ' ');
        now += b + (now[b] == ' ');
    }
    snprintf(out, n, "the same words in another order");
}

bool ckpt_read_file(const char *path, const struct ckpt_id *id, struct ckpt_buf *payload, char *err, size_t errlen)
{
    memset(payload, 0, sizeof *payload);
    struct ckpt_buf all;
    if (!read_verified(path, &all, err, errlen)) return false;
    char magic[8] = {0};
    uint64_t build = 0, scene = 0, olen = 0, plen = 0;
    bool ok;
    ckpt_get(&all, magic, 8);
    CKPT_GET(&all, build);
    CKPT_GET(&all, scene);
    CKPT_GET(&all, olen);
    char *opts = olen <= all.len - all.pos ? xmalloc(olen + 1) : NULL;
    if (opts) {
        ckpt_get(&all, opts, olen);
        opts[olen] = 0;
    }
    CKPT_GET(&all, plen);
    ok = false;
    if (!opts || all.short_read || plen != all.len - all.pos)
        snprintf(err, errlen, "%s: the checkpoint's layout is damaged", path);
    else if (build != id->build || !build)
        snprintf(err, errlen, "%s: written by another build of the renderer; resume with the binary that wrote it",
                 path);
    else if (scene != id->scene)
        snprintf(err, errlen, "%s: written for another scene (or the scene's files changed since)", path);
    else if (strcmp(opts, id->options)) {
        str_sanitize(opts);
        char diff[256];
        first_difference(opts, id->options, diff, sizeof diff);
        snprintf(err, errlen, "%s: written with other options: %s", path, diff);
    } else
        ok = true;
    free(opts);
    if (!ok) {
        ckpt_buf_free(&all);
        return false;
    }
    /* the payload moves to the front of the file's buffer, which becomes the caller's */
    memmove(all.p, all.p + all.pos, (size_t)plen);
    *payload = (struct ckpt_buf){.p = all.p, .len = (size_t)plen, .cap = all.cap};
    return true;
}
