/* Scrambled (0,2)-sequences (sobol02.h). */
#include "sampler/sobol02.h"

static uint32_t reverse_bits(uint32_t x)
{
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0F0F0F0Fu) | ((x & 0x0F0F0F0Fu) << 4);
    x = ((x >> 8) & 0x00FF00FFu) | ((x & 0x00FF00FFu) << 8);
    return (x >> 16) | (x << 16);
}

/* Every output bit depends only on the input bits of equal or lower significance (additions and
 * products with even constants), so on reversed bits it is an Owen scramble: a random
 * permutation of each interval's two halves, chosen by the digits above. */
static uint32_t laine_karras(uint32_t x, uint32_t seed)
{
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

/* Sobol's second dimension is the Pascal matrix mod 2 applied to the index: bit r of the reversed
 * result is the parity of the index bits k with C(k, r) odd, i.e. (Lucas) with k a bit-superset of
 * r. That sum over supersets of r takes five shift-xor steps instead of a loop over 32 direction
 * numbers; the result stays bit-reversed, which is the order the scramble below works in. */
static uint32_t sobol_dim1_reversed(uint32_t index)
{
    index ^= (index >> 1) & 0x55555555u;
    index ^= (index >> 2) & 0x33333333u;
    index ^= (index >> 4) & 0x0F0F0F0Fu;
    index ^= (index >> 8) & 0x00FF00FFu;
    index ^= index >> 16;
    return index;
}

static uint32_t mix(uint64_t key, uint32_t salt)
{
    uint64_t h = key ^ (0x9E3779B97F4A7C15ull * (salt + 1ull));
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ull;
    h ^= h >> 33;
    return (uint32_t)h;
}

/* Both Owen scrambles work on reversed bits; van der Corput is the reversal itself, so the index's
 * scramble is left reversed and the point's is reversed once at the end. */
double sobol02_sample(uint64_t key, uint32_t index, uint32_t dim)
{
    uint32_t pair = dim >> 1;
    uint32_t i = laine_karras(reverse_bits(index), mix(key, 2 * pair + 0x40000000u));
    uint32_t x = dim & 1 ? sobol_dim1_reversed(reverse_bits(i)) : reverse_bits(i);
    return reverse_bits(laine_karras(x, mix(key, dim))) * (1.0 / 4294967296.0);
}
