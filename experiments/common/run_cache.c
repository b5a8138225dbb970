/* Runs shared between studies (run_cache.h). */
#include "common/run_cache.h"
#include "base/util.h"
#include "common/outdir.h"
#include "io/checkpoint.h"
#include "mcmc/mlt_options.h"
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Options that say where and how a run writes, not what it renders. */
static bool output_only(const char *opt)
{
    static const char *const names[] = {"--out", "--quiet", "--checkpoint", "--resume"};
    for (size_t i = 0; i < sizeof names / sizeof *names; i++)
        if (!strcmp(opt, names[i])) return true;
    return false;
}

static bool is_option(const char *s) { return s[0] == '-' && s[1] == '-'; }

/* An MCMC option given once with its default value ("--p-large 0.1", "--pitp-rate 1"): the same
 * render as without it, so left out of the key; otherwise a study that spells a default out would
 * not meet one that leaves it to bin/render. Given twice, the later wins in bin/render, so neither
 * is left out. */
static bool given_once_at_default(char *const *argv, int argc, int i, int count)
{
    if (count != 2) return false;
    for (int j = 2; j < argc; j++)
        if (j != i && !strcmp(argv[j], argv[i])) return false;
    for (size_t k = 0; k < mlt_options_count; k++) {
        const struct mlt_option *d = &mlt_options[k];
        if (!d->cli || strcmp(d->cli, argv[i])) continue;
        if (!d->def || (d->type != MLT_OPTION_INT && d->type != MLT_OPTION_DOUBLE)) return false;
        char *end;
        double v = strtod(argv[i + 1], &end);
        return end != argv[i + 1] && !*end && v == strtod(d->def, NULL);
    }
    return false;
}

bool run_cache_key(const struct run_cache *rc, char *const *argv, int argc, char *key, size_t n)
{
    enum { MAX_ITEMS = 128 };
    int first[MAX_ITEMS], count[MAX_ITEMS], m = 0;
    for (int i = 2; i < argc;) { /* an item: an option and the values after it (or a lone word) */
        int j = i + 1;
        if (is_option(argv[i]))
            while (j < argc && !is_option(argv[j]))
                j++;
        if (!output_only(argv[i]) && !given_once_at_default(argv, argc, i, j - i)) {
            if (m == MAX_ITEMS) return false;
            first[m] = i;
            count[m++] = j - i;
        }
        i = j;
    }
    for (int a = 1; a < m; a++) /* insertion sort by the option's name: stable */
        for (int b = a; b > 0 && strcmp(argv[first[b - 1]], argv[first[b]]) > 0; b--) {
            int f = first[b], c = count[b];
            first[b] = first[b - 1], count[b] = count[b - 1];
            first[b - 1] = f, count[b - 1] = c;
        }
    size_t len = (size_t)snprintf(key, n, "run-cache-v1 build=%016llx scene=%016llx\n", (unsigned long long)rc->build,
                                  (unsigned long long)rc->scene);
    for (int a = 0; a < m && len < n; a++)
        for (int k = 0; k < count[a] && len < n; k++)
            len += (size_t)snprintf(key + len, n - len, "%s%c", argv[first[a] + k], k + 1 < count[a] ? ' ' : '\n');
    return len < n;
}

static void entry_path(const struct run_cache *rc, const char *key, char *out, size_t n)
{
    snprintf(out, n, "%s/%016llx", rc->dir, (unsigned long long)hash64(0, key, strlen(key)));
}

/* src to dst: a hard link, or a copy where none can be made (another file system; tests force the
 * copy with PSS_TEST_NO_HARDLINK set). */
static bool link_or_copy(const char *src, const char *dst)
{
    unlink(dst);
    if (!getenv("PSS_TEST_NO_HARDLINK") && link(src, dst) == 0) return true;
    size_t n; /* another file system: a copy, written atomically */
    void *bytes = read_file_bytes(src, &n);
    char err[4400];
    bool ok = bytes && write_bytes_atomic(dst, bytes, n, err, sizeof err);
    free(bytes);
    return ok;
}

static bool has_file(const char *dir, const char *name)
{
    char p[4200];
    snprintf(p, sizeof p, "%.4000s/%.64s", dir, name);
    return access(p, R_OK) == 0;
}

bool run_cache_fetch(const struct run_cache *rc, const char *key, const char *prefix)
{
    if (!rc->dir) return false;
    char entry[4096], p[4200];
    entry_path(rc, key, entry, sizeof entry);
    snprintf(p, sizeof p, "%s/key", entry);
    char *have = read_whole_file(p);
    bool match = have && !strcmp(have, key);
    free(have);
    if (!match || !has_file(entry, "exr") || !has_file(entry, "csv")) return false;
    DIR *d = opendir(entry);
    if (!d) return false;
    bool ok = true;
    for (struct dirent *de; ok && (de = readdir(d));) {
        if (de->d_name[0] == '.' || !strcmp(de->d_name, "key")) continue;
        char src[4400], dst[4400];
        snprintf(src, sizeof src, "%s/%s", entry, de->d_name);
        snprintf(dst, sizeof dst, "%s.%s", prefix, de->d_name);
        ok = link_or_copy(src, dst);
    }
    closedir(d);
    return ok;
}

static void remove_tree(const char *dir)
{
    DIR *d = opendir(dir);
    if (d) {
        for (struct dirent *de; (de = readdir(d));) {
            if (!strcmp(de->d_name, ".") || !strcmp(de->d_name, "..")) continue;
            char p[4400];
            snprintf(p, sizeof p, "%s/%s", dir, de->d_name);
            unlink(p);
        }
        closedir(d);
    }
    rmdir(dir);
}

/* A run's own file, as opposed to its checkpoint or a temporary being written. */
static bool run_file(const char *suffix)
{
    size_t n = strlen(suffix);
    return n && !strstr(suffix, ".tmp") && strncmp(suffix, "tmp", 3) && !(n >= 4 && !strcmp(suffix + n - 4, "ckpt"));
}

bool run_cache_store(const struct run_cache *rc, const char *key, const char *prefix, char *err, size_t errlen)
{
    if (errlen) *err = 0;
    if (!rc->dir) return true;
    char entry[4096], tmp[4200], p[4400];
    entry_path(rc, key, entry, sizeof entry);
    if (has_file(entry, "key")) return true;
    if (!outdir_make(rc->dir, err, errlen)) return false;
    snprintf(tmp, sizeof tmp, "%s.tmp%ld", entry, (long)getpid());
    remove_tree(tmp);
    if (mkdir(tmp, 0777) != 0) {
        snprintf(err, errlen, "cannot create %s: %s", tmp, strerror(errno));
        return false;
    }
    char dirpart[4096];
    snprintf(dirpart, sizeof dirpart, "%s", prefix);
    char *slash = strrchr(dirpart, '/');
    const char *base = slash ? slash + 1 : prefix;
    if (slash)
        *slash = 0;
    else
        snprintf(dirpart, sizeof dirpart, ".");
    size_t bl = strlen(base);
    DIR *d = opendir(dirpart);
    bool ok = d != NULL;
    for (struct dirent *de; ok && (de = readdir(d));) {
        if (strncmp(de->d_name, base, bl) || de->d_name[bl] != '.' || !run_file(de->d_name + bl + 1)) continue;
        char src[4400];
        snprintf(src, sizeof src, "%s/%s", dirpart, de->d_name);
        snprintf(p, sizeof p, "%s/%s", tmp, de->d_name + bl + 1);
        ok = link_or_copy(src, p);
    }
    if (d) closedir(d);
    snprintf(p, sizeof p, "%s/key", tmp);
    ok = ok && has_file(tmp, "exr") && has_file(tmp, "csv") && write_text_atomic(p, key, err, errlen);
    if (ok && rename(tmp, entry) != 0 && !has_file(entry, "key")) {
        snprintf(err, errlen, "cannot rename %s to %s: %s", tmp, entry, strerror(errno));
        ok = false;
    } else if (!ok && !*err) {
        snprintf(err, errlen, "cannot store the run %s in %s", prefix, rc->dir);
    }
    remove_tree(tmp); /* nothing left when the rename made it the entry; the loser's copy otherwise */
    return ok;
}
