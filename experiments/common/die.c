/* The error line (die.h). */
#include "common/die.h"
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

void vdie(int status, const char *prog, const char *fmt, va_list ap)
{
    fprintf(stderr, "%s: ", prog);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    exit(status);
}

void die(int status, const char *prog, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vdie(status, prog, fmt, ap);
}
