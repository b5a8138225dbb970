/* .obj and .wo3 readers. Both follow Tungsten's MeshIO/ObjLoader: OBJ polygons are fan-triangulated
 * (first, previous, current), every face corner becomes its own vertex, negative indices count back
 * from the last element defined so far; .wo3 is the raw vertex and triangle arrays. */
#include "io/mesh_io.h"
#include "base/input_limits.h"
#include "base/util.h"
#include <errno.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* base/input_limits.h's, which also keeps every count and index far inside int. */
#define MESH_MAX_ELEMS LIMIT_MESH_ELEMS

void raw_mesh_free(struct raw_mesh *m)
{
    if (!m) return;
    free(m->p);
    free(m->n);
    free(m->uv);
    free(m->tri);
    memset(m, 0, sizeof *m);
}

struct vec_list {
    double *v;
    int n, cap, dim;
};

static void list_push(struct vec_list *l, const double *x)
{
    if (l->n == l->cap) {
        l->cap = l->cap ? 2 * l->cap : 64;
        l->v = xrealloc(l->v, (size_t)l->cap * l->dim * sizeof(double));
    }
    memcpy(l->v + (size_t)l->n * l->dim, x, l->dim * sizeof(double));
    l->n++;
}

struct obj_state {
    struct vec_list pos, nrm, tex;
    /* output: one vertex per face corner */
    struct vec_list out_p, out_n, out_uv;
    int *tri;
    int ntri, tricap;
    bool all_n, any_uv;
};

/* Reads up to `max` numbers after the keyword; needs at least `min`. */
static int parse_numbers(char *s, double *out, int min, int max, long line, char *err, size_t errlen)
{
    int k = 0;
    char *tok, *save = NULL;
    for (tok = strtok_r(s, " \t\r\n", &save); tok; tok = strtok_r(NULL, " \t\r\n", &save)) {
        if (k == max) break;
        char *end;
        errno = 0;
        double d = strtod(tok, &end);
        if (end == tok || *end) {
            snprintf(err, errlen, "line %ld: expected a number, got '%.32s'", line, tok);
            return -1;
        }
        if (!isfinite(d)) {
            snprintf(err, errlen, "line %ld: non-finite number '%.32s'", line, tok);
            return -1;
        }
        out[k++] = d;
    }
    if (k < min) {
        snprintf(err, errlen, "line %ld: expected at least %d numbers", line, min);
        return -1;
    }
    return k;
}

/* OBJ index (1-based, negative = relative to the end) → 0-based, or -1 if out of range. */
static int resolve(long idx, int count)
{
    if (idx < 0) idx += (long)count + 1;
    if (idx < 1 || idx > count) return -1;
    return (int)idx - 1;
}

static bool parse_corner(struct obj_state *st, const char *tok, long line, char *err, size_t errlen)
{
    long idx[3] = {0, 0, 0};
    bool have[3] = {false, false, false};
    const char *s = tok;
    for (int i = 0; i < 3; i++) {
        if (*s != '/' && *s) {
            char *end;
            errno = 0;
            idx[i] = strtol(s, &end, 10);
            if (end == s || errno) {
                snprintf(err, errlen, "line %ld: malformed face vertex '%.32s'", line, tok);
                return false;
            }
            have[i] = true;
            s = end;
        }
        if (*s == '/')
            s++;
        else
            break;
    }
    if (*s || !have[0]) {
        snprintf(err, errlen, "line %ld: malformed face vertex '%.32s'", line, tok);
        return false;
    }
    int vi = resolve(idx[0], st->pos.n);
    int ti = have[1] ? resolve(idx[1], st->tex.n) : 0;
    int ni = have[2] ? resolve(idx[2], st->nrm.n) : 0;
    if (vi < 0 || ti < 0 || ni < 0) {
        snprintf(err, errlen, "line %ld: face index out of range in '%.32s'", line, tok);
        return false;
    }
    if (st->out_p.n >= MESH_MAX_ELEMS) {
        snprintf(err, errlen, "line %ld: more than %ld vertices (the renderer's limit)", line, LIMIT_MESH_ELEMS);
        return false;
    }
    list_push(&st->out_p, st->pos.v + 3 * (size_t)vi);
    double zero[3] = {0, 0, 0};
    list_push(&st->out_n, have[2] ? st->nrm.v + 3 * (size_t)ni : zero);
    list_push(&st->out_uv, have[1] ? st->tex.v + 2 * (size_t)ti : zero);
    st->all_n &= have[2];
    st->any_uv |= have[1];
    return true;
}

static void push_tri(struct obj_state *st, int a, int b, int c)
{
    if (st->ntri == st->tricap) {
        st->tricap = st->tricap ? 2 * st->tricap : 64;
        st->tri = xrealloc(st->tri, (size_t)st->tricap * 3 * sizeof(int));
    }
    int *t = st->tri + 3 * (size_t)st->ntri++;
    t[0] = a;
    t[1] = b;
    t[2] = c;
}

static bool parse_face(struct obj_state *st, char *s, long line, char *err, size_t errlen)
{
    int first = -1, prev = -1, count = 0;
    char *tok, *save = NULL;
    for (tok = strtok_r(s, " \t\r\n", &save); tok; tok = strtok_r(NULL, " \t\r\n", &save)) {
        if (!parse_corner(st, tok, line, err, errlen)) return false;
        int v = st->out_p.n - 1;
        if (count == 0)
            first = v;
        else if (count >= 2)
            push_tri(st, first, prev, v);
        prev = v;
        count++;
    }
    if (count < 3) {
        snprintf(err, errlen, "line %ld: a face needs at least 3 vertices", line);
        return false;
    }
    return true;
}

static bool parse_line(struct obj_state *st, char *s, long line, char *err, size_t errlen)
{
    while (*s == ' ' || *s == '\t')
        s++;
    size_t kw = strcspn(s, " \t\r\n");
    char *rest = s + kw;
    double x[3] = {0, 0, 0};
    if (kw == 1 && s[0] == 'v') {
        if (parse_numbers(rest, x, 3, 3, line, err, errlen) < 0) return false;
        if (st->pos.n >= MESH_MAX_ELEMS)
            return snprintf(err, errlen, "line %ld: more than %ld vertices (the renderer's limit)", line,
                            LIMIT_MESH_ELEMS),
                   false;
        list_push(&st->pos, x);
    } else if (kw == 2 && s[0] == 'v' && s[1] == 'n') {
        if (parse_numbers(rest, x, 3, 3, line, err, errlen) < 0) return false;
        if (st->nrm.n >= MESH_MAX_ELEMS)
            return snprintf(err, errlen, "line %ld: more than %ld normals (the renderer's limit)", line,
                            LIMIT_MESH_ELEMS),
                   false;
        list_push(&st->nrm, x);
    } else if (kw == 2 && s[0] == 'v' && s[1] == 't') {
        if (parse_numbers(rest, x, 1, 3, line, err, errlen) < 0) return false;
        if (st->tex.n >= MESH_MAX_ELEMS)
            return snprintf(err, errlen, "line %ld: more than %ld uvs (the renderer's limit)", line, LIMIT_MESH_ELEMS),
                   false;
        list_push(&st->tex, x);
    } else if (kw == 1 && s[0] == 'f') {
        return parse_face(st, rest, line, err, errlen);
    }
    /* Everything else (comments, groups, materials, smoothing groups, lines, points) carries no
     * triangle geometry: Tungsten's geometry-only path ignores it too. */
    return true;
}

static void obj_state_free(struct obj_state *st)
{
    free(st->pos.v);
    free(st->nrm.v);
    free(st->tex.v);
    free(st->out_p.v);
    free(st->out_n.v);
    free(st->out_uv.v);
    free(st->tri);
}

static vec3 *to_vec3(const struct vec_list *l)
{
    vec3 *v = xmalloc((size_t)(l->n ? l->n : 1) * sizeof(vec3));
    for (int i = 0; i < l->n; i++)
        v[i] = v3(l->v[3 * (size_t)i], l->v[3 * (size_t)i + 1], l->v[3 * (size_t)i + 2]);
    return v;
}

static FILE *open_regular(const char *path, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "cannot open: %s", strerror(errno));
        return NULL;
    }
    if (!file_is_regular(f)) {
        fclose(f);
        snprintf(err, errlen, "not a regular file");
        return NULL;
    }
    return f;
}

bool mesh_load_obj(const char *path, struct raw_mesh *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    FILE *f = open_regular(path, err, errlen);
    if (!f) return false;
    bool ok = mesh_read_obj(f, m, err, errlen);
    fclose(f);
    return ok;
}

bool mesh_read_obj(FILE *f, struct raw_mesh *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    struct obj_state st = {
        .pos.dim = 3, .nrm.dim = 3, .tex.dim = 2, .out_p.dim = 3, .out_n.dim = 3, .out_uv.dim = 2, .all_n = true};
    char *buf = NULL;
    size_t cap = 0;
    long line = 0;
    bool ok = true;
    while (ok && getline(&buf, &cap, f) != -1) {
        line++;
        ok = parse_line(&st, buf, line, err, errlen);
    }
    if (ok && ferror(f)) {
        snprintf(err, errlen, "read error: %s", strerror(errno));
        ok = false;
    }
    free(buf);
    if (!ok) str_sanitize(err); /* the message may quote the file's bytes */
    if (ok) {
        m->nverts = st.out_p.n;
        m->ntris = st.ntri;
        m->p = to_vec3(&st.out_p);
        m->n = st.all_n && st.out_n.n ? to_vec3(&st.out_n) : NULL;
        /* Tungsten: a corner without vt gets uv (0, 0), and the others keep theirs. */
        if (st.any_uv && st.out_uv.n) {
            m->uv = st.out_uv.v;
            st.out_uv.v = NULL;
        }
        m->tri = st.tri;
        st.tri = NULL;
    }
    obj_state_free(&st);
    return ok;
}

static uint64_t rd_u64(const unsigned char *b)
{
    uint64_t v = 0;
    for (int i = 7; i >= 0; i--)
        v = v << 8 | b[i];
    return v;
}

static uint32_t rd_u32(const unsigned char *b)
{
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

static float rd_f32(const unsigned char *b)
{
    uint32_t u = rd_u32(b);
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

static unsigned char *read_all(const char *path, size_t *len, char *err, size_t errlen)
{
    FILE *f = open_regular(path, err, errlen);
    if (!f) return NULL;
    size_t cap = 1 << 16, n = 0;
    unsigned char *b = xmalloc(cap);
    for (;;) {
        size_t r = fread(b + n, 1, cap - n, f);
        n += r;
        if (n < cap) break;
        cap *= 2;
        b = xrealloc(b, cap);
    }
    bool bad = ferror(f);
    fclose(f);
    if (bad) {
        snprintf(err, errlen, "read error");
        free(b);
        return NULL;
    }
    *len = n;
    return b;
}

bool mesh_load_wo3(const char *path, struct raw_mesh *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    size_t len;
    unsigned char *b = read_all(path, &len, err, errlen);
    if (!b) return false;
    bool ok = mesh_parse_wo3(b, len, m, err, errlen);
    free(b);
    return ok;
}

bool mesh_parse_wo3(const unsigned char *b, size_t len, struct raw_mesh *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    bool ok = false;
    const size_t VSZ = 32, TSZ = 16; /* 8 floats; 3 uint32 + 1 int32 */
    if (len < 16) {
        snprintf(err, errlen, "corrupt .wo3: truncated header (%zu bytes)", len);
        goto out;
    }
    uint64_t nv = rd_u64(b);
    if (nv > MESH_MAX_ELEMS) {
        snprintf(err, errlen, ".wo3 with %llu vertices, above the renderer's limit of %ld", (unsigned long long)nv,
                 LIMIT_MESH_ELEMS);
        goto out;
    }
    if (nv > (len - 16) / VSZ) {
        snprintf(err, errlen, "corrupt .wo3: vertex count %llu does not fit the file (%zu bytes)",
                 (unsigned long long)nv, len);
        goto out;
    }
    size_t off = 8 + nv * VSZ;
    uint64_t nt = rd_u64(b + off);
    off += 8;
    if (nt > MESH_MAX_ELEMS) {
        snprintf(err, errlen, ".wo3 with %llu triangles, above the renderer's limit of %ld", (unsigned long long)nt,
                 LIMIT_MESH_ELEMS);
        goto out;
    }
    if (nt * TSZ != len - off) {
        snprintf(err, errlen, "corrupt .wo3: %llu triangles need %llu bytes after the vertices, file has %zu",
                 (unsigned long long)nt, (unsigned long long)(nt * TSZ), len - off);
        goto out;
    }
    m->nverts = (int)nv;
    m->ntris = (int)nt;
    m->p = xmalloc((nv ? nv : 1) * sizeof(vec3));
    m->n = xmalloc((nv ? nv : 1) * sizeof(vec3));
    m->uv = xmalloc((nv ? nv : 1) * 2 * sizeof(double));
    m->tri = xmalloc((nt ? nt : 1) * 3 * sizeof(int));
    for (uint64_t i = 0; i < nv; i++) {
        const unsigned char *v = b + 8 + i * VSZ;
        float x[8];
        for (int j = 0; j < 8; j++) {
            x[j] = rd_f32(v + 4 * j);
            if (!isfinite(x[j])) {
                snprintf(err, errlen, "corrupt .wo3: vertex %llu has a non-finite value", (unsigned long long)i);
                goto out;
            }
        }
        m->p[i] = v3(x[0], x[1], x[2]);
        m->n[i] = v3(x[3], x[4], x[5]);
        m->uv[2 * i] = x[6];
        m->uv[2 * i + 1] = x[7];
    }
    for (uint64_t i = 0; i < nt; i++) {
        const unsigned char *t = b + off + i * TSZ;
        for (int j = 0; j < 3; j++) {
            uint32_t idx = rd_u32(t + 4 * j);
            if (idx >= nv) {
                snprintf(err, errlen, "corrupt .wo3: triangle %llu index %u out of range (%llu vertices)",
                         (unsigned long long)i, idx, (unsigned long long)nv);
                goto out;
            }
            m->tri[3 * i + j] = (int)idx;
        }
    }
    ok = true;
out:
    if (!ok) raw_mesh_free(m);
    return ok;
}

bool mesh_load(const char *path, struct raw_mesh *m, char *err, size_t errlen)
{
    memset(m, 0, sizeof *m);
    const char *dot = strrchr(path, '.');
    if (dot && strcasecmp(dot, ".obj") == 0) return mesh_load_obj(path, m, err, errlen);
    if (dot && strcasecmp(dot, ".wo3") == 0) return mesh_load_wo3(path, m, err, errlen);
    snprintf(err, errlen, "unknown mesh format (expected a .obj or .wo3 file)");
    return false;
}
