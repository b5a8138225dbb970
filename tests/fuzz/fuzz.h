/* The fuzz targets' entry functions: libFuzzer calls them through tests/fuzz/main/libfuzzer.c (one
 * executable per target, `make fuzz`), the Criterion suite fuzz_replay (test_fuzz_replay.c) feeds
 * them every regression input under tests/data/fuzz/TARGET/. Each takes one input, runs a reader on
 * it, frees what it made and aborts when the reader broke its contract: an error message that is
 * empty, longer than one line or carries control characters. */
#ifndef FUZZ_H
#define FUZZ_H

#include <stddef.h>
#include <stdint.h>

int fuzz_scene(const uint8_t *data, size_t size);
int fuzz_obj(const uint8_t *data, size_t size);
int fuzz_wo3(const uint8_t *data, size_t size);
int fuzz_checkpoint(const uint8_t *data, size_t size);
int fuzz_stats_csv(const uint8_t *data, size_t size);
int fuzz_texture(const uint8_t *data, size_t size);

/* A directory of this process's own (made once, removed at exit), for inputs that must be files. */
const char *fuzz_dir(void);
/* Writes n bytes to fuzz_dir()/name and returns the path (a static buffer per call site's name). */
const char *fuzz_write(const char *name, const void *data, size_t n, char *path, size_t pathlen);
/* Aborts unless err is one non-empty line of printable text. */
void fuzz_check_message(const char *err);

/* The raw texel file of the texture target and of the fuzz build's stand-in for OpenImageIO
 * (main/oiio_stub.c): width and height (16-bit little endian), channels, bits (0: float), then
 * w*h*channels little-endian floats. Returns the header's numbers, and the texels only if the
 * header passes texels_check_size and the data are exactly there (malloc'ed); false with a message
 * otherwise. */
int raw_texels_parse(const uint8_t *data, size_t size, const char *name, int *w, int *h, int *nc, int *bits, float **px,
                     char *err, size_t errlen);

#endif
