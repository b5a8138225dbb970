/* Fuzz target: the checkpoint reader (ckpt_read_file, core/io/checkpoint.c) and the readers of what it
 * returns: the threads' nested buffers, images, path vertices (core/path/path_checkpoint.c) and MLT
 * thread states (core/mcmc/chain_checkpoint.c), each followed by a first use of what was read.
 *
 * The first byte chooses the way in. Odd: the rest is the file as it is, which the checksum turns
 * away almost always. Even: the rest is the options text (up to a NUL) and the payload, written by
 * ckpt_write_file, so the checksum holds and the fuzzer reaches the layout and the payload; bit 1 then
 * makes the reader expect other options. */
#include "base/util.h"
#include "fuzz/fuzz.h"
#include "io/checkpoint.h"
#include "mcmc/chain.h"
#include "path/path_checkpoint.h"
#include "scene/scene.h"
#include <stdlib.h>
#include <string.h>

static void read_mlt(struct ckpt_buf *b, const struct scene *sc)
{
    struct chain ch[2];
    struct ctrl_path *path = xcalloc(2, sizeof *path);
    struct mmlt_path *x = xcalloc(2, sizeof *x);
    struct pss_opts po;
    pss_opts_default(&po, 4, 4);
    memset(ch, 0, sizeof ch);
    for (int i = 0; i < 2; i++) {
        pss_init(&ch[i].pss, &po, 1, (uint64_t)i);
        ch[i].path = &path[i];
        ch[i].x = &x[i];
    }
    rng r;
    long n = 0, ctrl_fail[2] = {0, 0};
    struct nonfinite nonfinite = {{0}};
    struct mlt_stats *st = xcalloc(1, sizeof *st);
    struct image *img = img_create(4, 4);
    struct mlt_thread t = {
        .ch = ch, .nk = 2, .r = &r, .n = &n, .nonfinite = &nonfinite, .st = st, .ctrl_fail = ctrl_fail, .img = img};
    if (mlt_thread_load(b, sc, &t))
        for (int i = 0; i < 2; i++) {
            /* a resumed chain's next move: a proposal that is rejected restores what it touched */
            pss_begin(&ch[i].pss, false);
            pss_reject(&ch[i].pss);
        }
    img_destroy(img);
    free(st);
    free(path);
    free(x);
}

/* A thread's buffer as PT and BDPT write it (core/mc/render.c): position, counts, image; the image
 * is read at the size the buffer states, as a run of that size would. */
static void read_mc_thread(struct ckpt_buf b)
{
    int at[3];
    long samples;
    struct nonfinite nf;
    CKPT_GET(&b, at);
    CKPT_GET(&b, samples);
    CKPT_GET(&b, nf);
    int wh[2] = {0, 0};
    if (b.len - b.pos >= sizeof wh) memcpy(wh, b.p + b.pos, sizeof wh);
    if (wh[0] < 1 || wh[0] > 64 || wh[1] < 1 || wh[1] > 64) return;
    struct image *im = img_create(wh[0], wh[1]);
    ckpt_get_image(&b, im);
    img_destroy(im);
}

/* The payload as the renderers lay it out: an 8-byte tag, PT/BDPT's pass and elapsed time (MLT's
 * header differs, and is fuzzed by the same bytes), then one buffer per thread (the seeds' 2). Each
 * buffer is read as PT/BDPT's, and again as vertices followed by an MLT thread. */
static void read_payload(struct ckpt_buf *p)
{
    static struct bsdf bsdfs[3];
    struct scene sc = {.bsdfs = bsdfs, .nbsdfs = 3};
    char tag[8];
    int first;
    double elapsed;
    ckpt_get(p, tag, sizeof tag);
    CKPT_GET(p, first);
    CKPT_GET(p, elapsed);
    struct ckpt_buf *t = ckpt_resume_threads(p, 2);
    if (!t) return;
    for (int i = 0; i < 2; i++) {
        read_mc_thread(t[i]);
        struct vertex v[4];
        if (ckpt_get_vertices(&t[i], &sc, v, 4))
            for (int k = 0; k < 4; k++)
                if (v[k].bc.b && (v[k].bc.b < bsdfs || v[k].bc.b >= bsdfs + 3)) __builtin_trap();
        read_mlt(&t[i], &sc);
    }
    free(t);
}

int fuzz_checkpoint(const uint8_t *data, size_t size)
{
    if (!size) return 0;
    char path[256], err[1024] = "", *opts = NULL;
    struct ckpt_id id = {.build = 0x5eed, .scene = 0xface, .options = "method=bdpt spp=4"};
    if (data[0] & 1) {
        fuzz_write("run.ckpt", data + 1, size - 1, path, sizeof path);
    } else {
        const uint8_t *nul = memchr(data + 1, 0, size - 1);
        size_t olen = nul ? (size_t)(nul - data - 1) : size - 1;
        opts = xmalloc(olen + 1);
        memcpy(opts, data + 1, olen);
        opts[olen] = 0;
        struct ckpt_buf payload = {0};
        if (nul) ckpt_put(&payload, nul + 1, size - 2 - olen);
        struct ckpt_id written = {.build = id.build, .scene = id.scene, .options = opts};
        snprintf(path, sizeof path, "%s/run.ckpt", fuzz_dir());
        if (!ckpt_write_file(path, &written, &payload, err, sizeof err)) abort();
        ckpt_buf_free(&payload);
        if (!(data[0] & 2)) id.options = opts;
    }
    struct ckpt_buf p;
    if (ckpt_read_file(path, &id, &p, err, sizeof err)) {
        read_payload(&p);
        ckpt_buf_free(&p);
    } else {
        fuzz_check_message(err);
    }
    free(opts);
    return 0;
}
