/* In-memory text written atomically (text_out.h). */
#include "common/text_out.h"
#include "base/util.h"
#include <stdlib.h>

FILE *text_out_open(struct text_out *t)
{
    *t = (struct text_out){0};
    t->f = open_memstream(&t->buf, &t->len);
    return t->f;
}

bool text_out_commit(struct text_out *t, const char *path, char *err, size_t errlen)
{
    if (!t->f) {
        snprintf(err, errlen, "%s: out of memory", path);
        return false;
    }
    fclose(t->f);
    t->f = NULL;
    return write_text_atomic(path, t->buf ? t->buf : "", err, errlen);
}

void text_out_free(struct text_out *t)
{
    if (t->f) fclose(t->f);
    free(t->buf);
    *t = (struct text_out){0};
}

bool text_out_save(struct text_out *t, const char *path, char *err, size_t errlen)
{
    bool ok = text_out_commit(t, path, err, errlen);
    text_out_free(t);
    return ok;
}
