/* One descriptor per field of struct mlt_opts (mlt.h) that a run can be given: its name, type,
 * default, bounds, the methods it applies to, whether it changes the numbers a run produces, its
 * help, its line in a run's CSV metadata and the options it cannot be combined with. Everything
 * that lists the options is derived from the table (mlt_options.c): bin/render's option entries
 * and --help, the checkpoint's identity text, the CSV metadata and mlt_render's checks. A new
 * option is one field in struct mlt_opts and one line in the table; tests/mcmc/test_options.c
 * fails when a field of struct mlt_opts has neither. No command-line code here: bin/render turns
 * the descriptors into its own entries. */
#ifndef MLT_OPTIONS_H
#define MLT_OPTIONS_H

#include "mcmc/mlt.h"
#include <stdbool.h>
#include <stddef.h>

/* The methods an option applies to, as bits of their index in mlt_option_methods. */
enum {
    APPLIES_PT = 1,
    APPLIES_BDPT = 2,
    APPLIES_PSSMLT = 4,
    APPLIES_MMLT = 8,
    APPLIES_PITP = 16,
    APPLIES_VEACH = 32,                                          /* --method mlt: Veach's MLT */
    APPLIES_MCMC = APPLIES_PSSMLT | APPLIES_MMLT | APPLIES_PITP, /* the primary-sample-space chains */
    APPLIES_CHAINS = APPLIES_MCMC | APPLIES_VEACH,               /* every Markov chain method */
    APPLIES_MULTIPLEXED = APPLIES_MMLT | APPLIES_PITP,
};
extern const char *const mlt_option_methods[]; /* pt, bdpt, pssmlt, mmlt, pitp, mlt, NULL */
/* The bit of a method's name (0 for an unknown one), and of a run's method. */
unsigned mlt_method_bit(const char *method);
unsigned mlt_method_mask(enum mlt_method m);

enum mlt_option_type { MLT_OPTION_FLAG, MLT_OPTION_INT, MLT_OPTION_DOUBLE, MLT_OPTION_CHOICE };

/* Where a descriptor's line goes in PREFIX.csv: the options around the controlled steps' failure
 * counts, in the order of csv_pos. */
enum mlt_csv_group { MLT_CSV_NONE, MLT_CSV_BEFORE_COUNTS, MLT_CSV_AFTER_COUNTS };

struct mlt_option {
    const char *key; /* the identity's and the coverage test's name: the field's */
    const char *cli; /* "--p-large" when bin/render takes it; NULL: set by the tools from their own */
    enum mlt_option_type type;
    size_t offset, size;        /* the field in struct mlt_opts */
    const char *field;          /* its path there ("pss.sigma") */
    const char *def;            /* the default as it would be given; NULL: what mlt_opts_defaults leaves */
    double lo, hi;              /* MLT_OPTION_INT, MLT_OPTION_DOUBLE */
    const char *const *choices; /* MLT_OPTION_CHOICE: NULL-terminated, indexed by the field's value */
    const char *arg;            /* the value's name in the help */
    unsigned methods;           /* APPLIES_ bits */
    bool numbers;               /* changes the numbers (image, statistics, checkpoint state) */
    const char *help;
    /* PREFIX.csv: "# csv_key VALUE"; VALUE is csv_values[value] when given (flags), the choice's
     * name, or the number; csv_effective: the default's when the method does not apply. */
    enum mlt_csv_group csv_group;
    int csv_pos;
    const char *csv_key;
    const char *const *csv_values;
    bool csv_effective;
    bool csv_own; /* its line only in the runs of the methods it applies to (the others' CSVs keep theirs) */
    bool (*csv_if)(const struct mlt_opts *o); /* its line only when this is true (NULL: always) */
    /* When the field is not at its default: true (with a message) when the other options rule it out. */
    bool (*conflict)(const struct mlt_opts *o, char *err, size_t errlen);
};

extern const struct mlt_option mlt_options[];
extern const size_t mlt_options_count;

/* The descriptor of a key ("small_step"), or NULL. */
const struct mlt_option *mlt_option_find(const char *key);
/* The defaults: pss_opts_default's numbers (film width, height 1) and every descriptor's def. */
void mlt_opts_defaults(struct mlt_opts *o);
/* The field's value as a double (integers of any size, bools, enums). */
double mlt_option_get(const struct mlt_option *d, const struct mlt_opts *o);
void mlt_option_set(const struct mlt_option *d, struct mlt_opts *o, double v);
bool mlt_option_at_default(const struct mlt_option *d, const struct mlt_opts *o);
/* The value as text: the CSV's (with csv_values) when csv, else the identity's. */
void mlt_option_format(const struct mlt_option *d, const struct mlt_opts *o, bool csv, char *buf, size_t n);
/* " key=value" for every number-changing descriptor, in table order: the checkpoint identity's
 * MCMC part. Returns the length written (as snprintf). */
int mlt_options_identity(const struct mlt_opts *o, char *buf, size_t n);
/* The descriptors of a CSV group in their order; returns how many (at most max). */
size_t mlt_options_csv(enum mlt_csv_group g, const struct mlt_option **out, size_t max);
/* The checks of every descriptor not at its default (mlt_render calls it). */
bool mlt_options_check(const struct mlt_opts *o, char *err, size_t errlen);

#endif
