/* EXR encoding through OpenEXR's C core into a memory buffer (see image_encode.h for why). */
#include "base/util.h"
#include "io/image_encode.h"
#include <OpenEXR/openexr.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct membuf {
    unsigned char *p;
    size_t len, cap;
    char msg[256]; /* the library's last error message */
};

/* The library writes at offsets: the header, the chunks, then the offset table back near the start. */
static int64_t mem_write(exr_const_context_t ctxt, void *user, const void *buf, uint64_t sz, uint64_t offset,
                         exr_stream_error_func_ptr_t error_cb)
{
    (void)ctxt;
    (void)error_cb;
    struct membuf *m = user;
    size_t end = (size_t)(offset + sz);
    if (end > m->cap) {
        size_t cap = m->cap ? m->cap : 65536;
        while (cap < end)
            cap *= 2;
        m->p = xrealloc(m->p, cap);
        m->cap = cap;
    }
    if (offset > m->len) memset(m->p + m->len, 0, (size_t)offset - m->len);
    memcpy(m->p + offset, buf, (size_t)sz);
    if (end > m->len) m->len = end;
    return (int64_t)sz;
}

static void keep_message(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    void *user = NULL;
    if (exr_get_user_data(ctxt, &user) == EXR_ERR_SUCCESS && user)
        snprintf(((struct membuf *)user)->msg, sizeof((struct membuf *)user)->msg, "%s (%s)", msg,
                 exr_get_error_code_as_string(code));
}

static bool failed(exr_result_t rv, const struct membuf *m, const char *what, char *err, size_t errlen)
{
    if (rv == EXR_ERR_SUCCESS) return false;
    snprintf(err, errlen, "OpenEXR: %s: %s", what, m->msg[0] ? m->msg : exr_get_default_error_message(rv));
    return true;
}

/* The chunks of 16 scanlines (ZIP's block), each channel read from the interleaved RGB rows. */
static exr_result_t write_chunks_of(exr_context_t ctx, int w, int h, const float *px)
{
    int32_t lines;
    exr_result_t rv = exr_get_scanlines_per_chunk(ctx, 0, &lines);
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    bool started = false;
    for (int y = 0; rv == EXR_ERR_SUCCESS && y < h; y += lines) {
        exr_chunk_info_t ci;
        rv = exr_write_scanline_chunk_info(ctx, 0, y, &ci);
        if (rv != EXR_ERR_SUCCESS) break;
        rv = started ? exr_encoding_update(ctx, 0, &ci, &enc) : exr_encoding_initialize(ctx, 0, &ci, &enc);
        if (rv != EXR_ERR_SUCCESS) break;
        for (int c = 0; c < enc.channel_count; c++) {
            exr_coding_channel_info_t *ch = &enc.channels[c];
            int k = ch->channel_name[0] == 'R' ? 0 : ch->channel_name[0] == 'G' ? 1 : 2;
            ch->encode_from_ptr = (const uint8_t *)(px + ((size_t)y * w * 3 + k));
            ch->user_pixel_stride = 3 * sizeof(float);
            ch->user_line_stride = 3 * sizeof(float) * w;
            ch->user_data_type = EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = sizeof(float);
        }
        if (!started) rv = exr_encoding_choose_default_routines(ctx, 0, &enc);
        started = true;
        if (rv == EXR_ERR_SUCCESS) rv = exr_encoding_run(ctx, 0, &enc);
    }
    if (started) {
        exr_result_t d = exr_encoding_destroy(ctx, &enc);
        if (rv == EXR_ERR_SUCCESS) rv = d;
    }
    return rv;
}

bool exr_encode_rgb(int w, int h, const float *px, unsigned char **bytes, size_t *len, char *err, size_t errlen)
{
    struct membuf m = {0};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.user_data = &m;
    init.write_fn = mem_write;
    init.error_handler_fn = keep_message;
    exr_context_t ctx = NULL;
    int part;
    exr_result_t rv = exr_start_write(&ctx, "memory", EXR_WRITE_FILE_DIRECTLY, &init);
    bool bad = failed(rv, &m, "start", err, errlen);
    if (!bad) bad = failed(exr_add_part(ctx, "", EXR_STORAGE_SCANLINE, &part), &m, "part", err, errlen);
    if (!bad)
        bad = failed(exr_initialize_required_attr_simple(ctx, part, w, h, EXR_COMPRESSION_ZIP), &m, "header", err,
                     errlen);
    static const char *const names[] = {"R", "G", "B"};
    for (int c = 0; c < 3 && !bad; c++)
        bad = failed(exr_add_channel(ctx, part, names[c], EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR, 1, 1), &m,
                     "channel", err, errlen);
    if (!bad) bad = failed(exr_write_header(ctx), &m, "header", err, errlen);
    if (!bad) bad = failed(write_chunks_of(ctx, w, h, px), &m, "pixels", err, errlen);
    if (ctx) { /* exr_finish writes the offset table */
        exr_result_t f = exr_finish(&ctx);
        if (!bad) bad = failed(f, &m, "finish", err, errlen);
    }
    if (bad) {
        free(m.p);
        return false;
    }
    *bytes = m.p;
    *len = m.len;
    return true;
}
