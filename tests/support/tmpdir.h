/* A scratch directory per test, removed with everything in it. */
#ifndef TMPDIR_H
#define TMPDIR_H

#include <stddef.h>

/* Creates /tmp/NAME-XXXXXX into dir (at least 64 bytes); the test fails if it cannot. */
void tmpdir_make(char *dir, size_t n, const char *name);
/* Removes dir and its contents; nothing when dir is empty. */
void tmpdir_remove(const char *dir);

#endif
