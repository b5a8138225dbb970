#include "support/tmpdir.h"
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>

void tmpdir_make(char *dir, size_t n, const char *name)
{
    snprintf(dir, n, "/tmp/%s-XXXXXX", name);
    cr_assert(mkdtemp(dir), "cannot create %s", dir);
}

void tmpdir_remove(const char *dir)
{
    if (!dir[0]) return;
    char cmd[512];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
}
