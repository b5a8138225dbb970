#include "common/cli.h"
#include "io/oiio.h"
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

void cli_fail(const char *prog, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", prog);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    exit(2);
}

void cli_require_image_output(const char *prog)
{
    char err[1024];
    if (oiio_module_present(err, sizeof err)) return;
    fprintf(stderr, "%s: %s\n", prog, err);
    exit(1);
}

long cli_long(const char *prog, const char *opt, const char *val, long lo, long hi)
{
    char *end;
    errno = 0;
    long v = strtol(val, &end, 10);
    if (errno || end == val || *end || v < lo || v > hi)
        cli_fail(prog, "%s: expected an integer in [%ld, %ld], got '%s'", opt, lo, hi, val);
    return v;
}

double cli_double(const char *prog, const char *opt, const char *val, double lo, double hi)
{
    char *end;
    errno = 0;
    double v = strtod(val, &end);
    if (errno || end == val || *end || !isfinite(v) || v < lo || v > hi)
        cli_fail(prog, "%s: expected a number in [%g, %g], got '%s'", opt, lo, hi, val);
    return v;
}

uint64_t cli_u64(const char *prog, const char *opt, const char *val)
{
    char *end;
    errno = 0;
    unsigned long long v = strtoull(val, &end, 10);
    if (errno || end == val || *end || val[0] == '-') cli_fail(prog, "%s: expected a non-negative integer, got '%s'", opt, val);
    return (uint64_t)v;
}

const char *cli_value(const char *prog, int argc, char **argv, int *i)
{
    if (*i + 1 >= argc) cli_fail(prog, "%s needs a value (see --help)", argv[*i]);
    return argv[++*i];
}
