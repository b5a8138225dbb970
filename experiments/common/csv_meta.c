/* CSV metadata lines (csv_meta.h). */
#include "common/csv_meta.h"
#include "version.h"
#include <stdarg.h>

void csv_meta(FILE *f, const char *key, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs(key ? "# " : "#", f);
    if (key) fputs(key, f);
    fputc(' ', f);
    vfprintf(f, fmt, ap);
    fputc('\n', f);
    va_end(ap);
}

void csv_meta_commit(FILE *f) { csv_meta(f, "commit", "%s", GIT_COMMIT); }

void csv_meta_head(FILE *f, const char *title, const char *scene, const char *scale)
{
    if (title) csv_meta(f, NULL, "%s", title);
    csv_meta(f, "scene", "%s", scene);
    csv_meta_commit(f);
    csv_meta(f, "scale", "%s", scale);
}
