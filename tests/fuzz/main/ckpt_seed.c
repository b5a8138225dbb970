/* Turns a checkpoint file into a seed for the checkpoint target's even way in (fuzz_checkpoint.c):
 * a 0 byte, the options text, a NUL, the payload. Layout as core/io/checkpoint.c writes it. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: ckpt_seed RUN.ckpt SEED\n");
        return 2;
    }
    FILE *f = fopen(argv[1], "rb");
    if (!f) return perror(argv[1]), 2;
    static unsigned char b[1 << 26];
    size_t n = fread(b, 1, sizeof b, f);
    fclose(f);
    uint64_t olen, plen;
    if (n < 48) return fprintf(stderr, "%s: too short\n", argv[1]), 2;
    memcpy(&olen, b + 24, 8);
    if (olen > n - 48) return fprintf(stderr, "%s: bad layout\n", argv[1]), 2;
    memcpy(&plen, b + 32 + olen, 8);
    if (plen != n - 48 - olen) return fprintf(stderr, "%s: bad layout\n", argv[1]), 2;
    FILE *o = fopen(argv[2], "wb");
    if (!o) return perror(argv[2]), 2;
    fputc(0, o);
    fwrite(b + 32, 1, olen, o);
    fputc(0, o);
    fwrite(b + 40 + olen, 1, plen, o);
    return fclose(o) ? 2 : 0;
}
