/* Expected-value splatting of the current and proposed states (see splat_ev.h). */
#include "mcmc/splat_ev.h"

void splat_list_weighted(struct image *img, const struct splat_list *l, double wgt, long *dropped)
{
    if (wgt <= 0) return;
    for (int i = 0; i < l->n; i++)
        splat_finite(img, l->s[i].px, l->s[i].py, vscale(l->s[i].c, wgt), dropped);
}

void splat_ev(struct image *img, struct chain *c, const struct splat_list *l, double f, double a)
{
    if (f > 0) splat_list_weighted(img, l, a * c->scale / f, c->dropped);
    owe_current(c, a);
}

void splat_ev_step(struct image *img, struct chain *c, const struct splat_list *l, double f, double a, bool large)
{
    if (!(c->mis_pl > 0)) {
        splat_ev(img, c, l, f, a);
        return;
    }
    if (f > 0) splat_list_weighted(img, l, (a + (large ? 1 : 0)) / (f / c->scale + c->mis_pl), c->dropped);
    owe_current(c, a);
}

void owe_current(struct chain *c, double a)
{
    if (c->f > 0) c->pending += 1 - a;
}

void pay_current(struct image *img, struct chain *c)
{
    if (c->f > 0)
        splat_list_weighted(img, &c->cur,
                            c->mis_pl > 0 ? c->pending / (c->f / c->scale + c->mis_pl) : c->pending * c->scale / c->f,
                            c->dropped);
    c->pending = 0;
}

void move_to(struct image *img, struct chain *c, const struct splat_list *l, double f)
{
    pay_current(img, c);
    c->cur.n = l->n;
    /* element by element: a state holds one splat or a few, and gcc's memcpy of a variable size
     * (vector_loop strategy) cost ~200 instructions per accepted move, 5 % of an MMLT iteration */
    for (int i = 0; i < l->n; i++)
        c->cur.s[i] = l->s[i];
    c->f = f;
}
