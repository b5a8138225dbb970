/* A text output built in memory and written atomically: the tools' CSV and Markdown files appear
 * complete or not at all (an interrupted run never leaves half a table for a script to read). */
#ifndef TEXT_OUT_H
#define TEXT_OUT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

struct text_out {
    FILE *f; /* write here (fprintf, csv_meta, ...) */
    char *buf;
    size_t len;
};

/* Opens the in-memory stream; t->f is NULL when memory is exhausted (text_out_save then fails). */
FILE *text_out_open(struct text_out *t);
/* Closes the stream and writes its text to path atomically; false with a message in err. The text
 * stays in t->buf (NUL-terminated) until text_out_free. */
bool text_out_commit(struct text_out *t, const char *path, char *err, size_t errlen);
void text_out_free(struct text_out *t);
/* text_out_commit, then text_out_free: the usual single call. */
bool text_out_save(struct text_out *t, const char *path, char *err, size_t errlen);

#endif
