/* Programmer-error checks and allocation that cannot fail silently (Redis-style). */
#ifndef UTIL_H
#define UTIL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

void *xmalloc(size_t n);
void *xcalloc(size_t n, size_t size);
void *xrealloc(void *p, size_t n);
char *xstrdup(const char *s);
/* Replaces control characters (bytes below 32, and 127) by '?': an error line that echoes a file's
 * bytes stays one line and cannot drive the terminal. */
void str_sanitize(char *s);
/* Whether an open file is a regular one: a device or a FIFO a scene names (/dev/zero) may never
 * end, and its reader would grow its buffer until memory runs out. */
bool file_is_regular(FILE *f);
void die_assert(const char *expr, const char *file, int line);
#define ASSERT(e) ((e) ? (void)0 : die_assert(#e, __FILE__, __LINE__))

/* Writes through a temporary file beside `path`, then renames: readers never see a partial file.
 * `write` is called with the temporary path and puts only the reason for a failure into its err
 * (write_chunks does). On failure the temporary is removed, the file at `path` is untouched and err
 * is one line naming `path`: "PATH: cannot write (REASON); the previous file is left as it was". */
typedef bool (*write_fn)(const char *tmp_path, void *ctx, char *err, size_t errlen);
bool atomic_write(const char *path, write_fn write, void *ctx, char *err, size_t errlen);
/* Creates `path` holding the chunks one after another, fsync'ed and closed, every call checked;
 * false with strerror's reason in err when one fails. Tests only: with PSS_TEST_WRITE_STALL_MS set,
 * a write of two or more chunks pauses that long after the first half of them, so that a test can
 * kill a process inside a write (a checkpoint passes its payload in two halves). */
struct chunk {
    const void *p;
    size_t n;
};
bool write_chunks(const char *path, const struct chunk *c, int n, char *err, size_t errlen);
/* A whole file as a NUL-terminated string (the caller frees it), or NULL when it cannot be read. */
char *read_whole_file(const char *path);
/* The same for any file: its bytes (NUL-terminated too) and their number in *n. */
void *read_file_bytes(const char *path, size_t *n);

#endif

/* Atomically writes a NUL-terminated text buffer, or n bytes, to `path`. */
bool write_text_atomic(const char *path, const char *text, char *err, size_t errlen);
bool write_bytes_atomic(const char *path, const void *p, size_t n, char *err, size_t errlen);
