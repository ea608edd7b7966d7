/*
 * files.c - reading the course files.
 *
 * Every file is read as text lines (LF or CRLF, blank lines skipped, spaces or
 * TABs between numbers); numbers are read with strtod in the C locale.
 *
 * Camera: UFPE layout (C; N; V; d hx hy), the UFRPE layouts N; V; d; hx; hy; C
 *         and C; N; V; hx hy; d (told apart by how many numbers each line holds),
 *         or "key = value" lines (C, N, V, d, hx, hy).
 * Lighting: UFPE (Pl; ka; Ia; kd; Od; ks; Il; n), UFPE multi-light (the first
 *         light is used, with a warning), UFRPE positional (Iamb Ka Il Pl Kd Od Ks n)
 *         or "key = value" lines (Iamb, Ka, Il, Pl, Kd, Od, Ks, eta).
 * Object: .byu triangle mesh "nv nt", nv points, nt triangles (1-based indices).
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raster.h"

#define MAX_NUMS 64

typedef struct {
    int lineno;             /* line in the file, from 1 */
    char key[32];           /* for "key = value" lines, else "" */
    int count;              /* numbers on the line */
    double v[MAX_NUMS];
    int bad;                /* something on the line that is not a number */
} Line;

typedef struct {
    int nlines;
    Line *lines;
} TextFile;

static char *slurp(const char *path)
{
    FILE *fp = fopen(path, "rb");
    char *buf;
    long size;

    if (fp == NULL) {
        fprintf(stderr, "error: cannot open %s\n", path);
        return NULL;
    }
    fseek(fp, 0, SEEK_END);
    size = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    if (size < 0)
        size = 0;
    buf = malloc((size_t)size + 1);
    if (buf == NULL) {
        fclose(fp);
        fprintf(stderr, "error: out of memory reading %s\n", path);
        return NULL;
    }
    size = (long)fread(buf, 1, (size_t)size, fp);
    buf[size] = '\0';
    fclose(fp);
    return buf;
}

/* splits a text into lines of numbers; blank lines are left out */
static int load_text(const char *path, TextFile *tf)
{
    char *text = slurp(path);
    char *p;
    int lineno = 0, cap = 64;

    if (text == NULL)
        return 0;
    tf->nlines = 0;
    tf->lines = malloc(cap * sizeof *tf->lines);

    p = text;
    while (*p) {
        char *end = p;
        Line ln;
        char *s;

        while (*end && *end != '\n')
            end++;
        if (*end == '\n')
            *end++ = '\0';
        lineno++;

        memset(&ln, 0, sizeof ln);
        ln.lineno = lineno;
        s = p;
        /* "key = value" */
        {
            char *eq = strchr(s, '=');
            if (eq != NULL) {
                char *k = s;
                size_t len;
                while (isspace((unsigned char)*k))
                    k++;
                len = (size_t)(eq - k);
                while (len > 0 && isspace((unsigned char)k[len - 1]))
                    len--;
                if (len >= sizeof ln.key)
                    len = sizeof ln.key - 1;
                memcpy(ln.key, k, len);
                ln.key[len] = '\0';
                s = eq + 1;
            }
        }
        for (;;) {
            char *q;
            double d;
            while (*s == ' ' || *s == '\t' || *s == '\r' || *s == ',' || *s == '\f' || *s == '\v')
                s++;
            if (*s == '\0')
                break;
            d = strtod(s, &q);
            if (q == s || !isfinite(d)) {
                ln.bad = 1;
                break;
            }
            if (ln.count < MAX_NUMS)
                ln.v[ln.count] = d;
            ln.count++;
            s = q;
        }
        p = end;

        if (ln.count == 0 && ln.key[0] == '\0' && !ln.bad)
            continue;    /* blank line */
        if (tf->nlines == cap) {
            cap *= 2;
            tf->lines = realloc(tf->lines, cap * sizeof *tf->lines);
        }
        tf->lines[tf->nlines++] = ln;
    }
    free(text);
    return 1;
}

/* all the numbers of the file, in order */
static int flatten(const TextFile *tf, double *out, int max)
{
    int i, k, n = 0;
    for (i = 0; i < tf->nlines; i++)
        for (k = 0; k < tf->lines[i].count && k < MAX_NUMS; k++) {
            if (n < max)
                out[n] = tf->lines[i].v[k];
            n++;
        }
    return n;
}

static int key_is(const char *key, const char *name)
{
    while (*key && *name) {
        if (tolower((unsigned char)*key) != tolower((unsigned char)*name))
            return 0;
        key++;
        name++;
    }
    return *key == '\0' && *name == '\0';
}

static int has_keys(const TextFile *tf)
{
    int i;
    for (i = 0; i < tf->nlines; i++)
        if (tf->lines[i].key[0])
            return 1;
    return 0;
}

static Vec3 vec_of(const double *v) { return vec3(v[0], v[1], v[2]); }

/* ----------------------------------------------------------------- camera */

static int layout_is(const TextFile *tf, const int *counts, int n)
{
    int i;
    if (tf->nlines != n)
        return 0;
    for (i = 0; i < n; i++)
        if (tf->lines[i].count != counts[i])
            return 0;
    return 1;
}

int read_camera(const char *path, Camera *cam)
{
    TextFile tf;
    double v[64];
    int n, i;
    static const int ufpe[] = {3, 3, 3, 3};
    static const int ufrpe6[] = {3, 3, 1, 1, 1, 3};
    static const int ufrpe5[] = {3, 3, 3, 2, 1};

    if (!load_text(path, &tf))
        return 0;

    if (has_keys(&tf)) {
        int got = 0;
        for (i = 0; i < tf.nlines; i++) {
            Line *ln = &tf.lines[i];
            if (key_is(ln->key, "C") && ln->count >= 3) { cam->C = vec_of(ln->v); got |= 1; }
            else if (key_is(ln->key, "N") && ln->count >= 3) { cam->N = vec_of(ln->v); got |= 2; }
            else if (key_is(ln->key, "V") && ln->count >= 3) { cam->V = vec_of(ln->v); got |= 4; }
            else if (key_is(ln->key, "d") && ln->count >= 1) { cam->d = ln->v[0]; got |= 8; }
            else if (key_is(ln->key, "hx") && ln->count >= 1) { cam->hx = ln->v[0]; got |= 16; }
            else if (key_is(ln->key, "hy") && ln->count >= 1) { cam->hy = ln->v[0]; got |= 32; }
        }
        free(tf.lines);
        if (got != 63) {
            fprintf(stderr, "error: %s: key = value camera needs C, N, V, d, hx and hy\n", path);
            return 0;
        }
        fprintf(stderr, "note: %s read as a key = value camera\n", path);
        return 1;
    }

    n = flatten(&tf, v, 64);
    if (n < 12) {
        fprintf(stderr, "error: %s: a camera needs 12 numbers (C, N, V, d hx hy), found %d\n",
                path, n);
        free(tf.lines);
        return 0;
    }
    if (layout_is(&tf, ufrpe6, 6)) {
        cam->N = vec_of(v);
        cam->V = vec_of(v + 3);
        cam->d = v[6];
        cam->hx = v[7];
        cam->hy = v[8];
        cam->C = vec_of(v + 9);
        fprintf(stderr, "note: %s read as a UFRPE camera (N; V; d; hx; hy; C)\n", path);
    } else if (layout_is(&tf, ufrpe5, 5)) {
        cam->C = vec_of(v);
        cam->N = vec_of(v + 3);
        cam->V = vec_of(v + 6);
        cam->hx = v[9];
        cam->hy = v[10];
        cam->d = v[11];
        fprintf(stderr, "note: %s read as a UFRPE camera (C; N; V; hx hy; d)\n", path);
    } else {
        if (!layout_is(&tf, ufpe, 4))
            fprintf(stderr, "warning: %s: unusual camera layout, read as C; N; V; d hx hy\n", path);
        cam->C = vec_of(v);
        cam->N = vec_of(v + 3);
        cam->V = vec_of(v + 6);
        cam->d = v[9];
        cam->hx = v[10];
        cam->hy = v[11];
        if (n > 12)
            fprintf(stderr, "warning: %s: %d numbers after the camera ignored\n", path, n - 12);
    }
    free(tf.lines);
    return 1;
}

/* --------------------------------------------------------------- lighting */

int read_lighting(const char *path, Lighting *l)
{
    TextFile tf;
    double v[256];
    int n, i;

    if (!load_text(path, &tf))
        return 0;

    memset(l, 0, sizeof *l);
    if (has_keys(&tf)) {
        int got = 0;
        for (i = 0; i < tf.nlines; i++) {
            Line *ln = &tf.lines[i];
            if ((key_is(ln->key, "Iamb") || key_is(ln->key, "Ia")) && ln->count >= 3) { l->Ia = vec_of(ln->v); got |= 1; }
            else if (key_is(ln->key, "Ka") && ln->count >= 1) { l->ka = ln->v[0]; got |= 2; }
            else if (key_is(ln->key, "Il") && ln->count >= 3) { l->Il = vec_of(ln->v); got |= 4; }
            else if (key_is(ln->key, "Pl") && ln->count >= 3) { l->Pl = vec_of(ln->v); got |= 8; }
            else if (key_is(ln->key, "Kd") && ln->count >= 1) {
                if (ln->count >= 3)
                    l->kd = vec_of(ln->v);
                else
                    l->kd = vec3(ln->v[0], ln->v[0], ln->v[0]);
                got |= 16;
            }
            else if (key_is(ln->key, "Od") && ln->count >= 3) { l->Od = vec_of(ln->v); got |= 32; }
            else if (key_is(ln->key, "Ks") && ln->count >= 1) { l->ks = ln->v[0]; got |= 64; }
            else if ((key_is(ln->key, "eta") || key_is(ln->key, "n")) && ln->count >= 1) { l->n = ln->v[0]; got |= 128; }
        }
        free(tf.lines);
        if (got != 255) {
            fprintf(stderr, "error: %s: key = value lighting needs Iamb, Ka, Il, Pl, Kd, Od, Ks, eta\n", path);
            return 0;
        }
        fprintf(stderr, "note: %s read as a key = value lighting file\n", path);
        return 1;
    }

    n = flatten(&tf, v, 256);
    if (tf.nlines >= 8 && tf.lines[0].count == 3 && tf.lines[1].count == 1 &&
        tf.lines[2].count == 3 && tf.lines[3].count == 1 && n >= 16) {
        /* UFPE: Pl; ka; Ia; kd; Od; ks; Il; n */
        l->Pl = vec_of(v);
        l->ka = v[3];
        l->Ia = vec_of(v + 4);
        l->kd = vec3(v[7], v[7], v[7]);
        l->Od = vec_of(v + 8);
        l->ks = v[11];
        l->Il = vec_of(v + 12);
        l->n = v[15];
        if (n > 16)
            fprintf(stderr, "warning: %s: %d numbers after the lighting ignored\n", path, n - 16);
    } else if (tf.nlines >= 9 && tf.lines[0].count == 1 && tf.lines[1].count == 3 && n >= 17) {
        /* UFPE multi: ka; Ia; kd; Od; ks; n; L; then L times Pl; Il */
        int L;
        l->ka = v[0];
        l->Ia = vec_of(v + 1);
        l->kd = vec3(v[4], v[4], v[4]);
        l->Od = vec_of(v + 5);
        l->ks = v[8];
        l->n = v[9];
        L = (int)v[10];
        l->Pl = vec_of(v + 11);
        l->Il = vec_of(v + 14);
        if (L != 1)
            fprintf(stderr, "warning: %s: %d lights; seed 000 has one light, only the first is used\n",
                    path, L);
        fprintf(stderr, "note: %s read as a UFPE multi-light file\n", path);
    } else if (n >= 18) {
        /* UFRPE: Iamb(3) Ka Il(3) Pl(3) Kd(3) Od(3) Ks n */
        l->Ia = vec_of(v);
        l->ka = v[3];
        l->Il = vec_of(v + 4);
        l->Pl = vec_of(v + 7);
        l->kd = vec_of(v + 10);
        l->Od = vec_of(v + 13);
        l->ks = v[16];
        l->n = v[17];
        fprintf(stderr, "note: %s read as a UFRPE lighting file (Iamb Ka Il Pl Kd Od Ks n)\n", path);
    } else if (n >= 16) {
        l->Pl = vec_of(v);
        l->ka = v[3];
        l->Ia = vec_of(v + 4);
        l->kd = vec3(v[7], v[7], v[7]);
        l->Od = vec_of(v + 8);
        l->ks = v[11];
        l->Il = vec_of(v + 12);
        l->n = v[15];
        fprintf(stderr, "warning: %s: unusual layout, read as Pl; ka; Ia; kd; Od; ks; Il; n\n", path);
    } else {
        fprintf(stderr, "error: %s: a lighting file needs 16 numbers, found %d\n", path, n);
        free(tf.lines);
        return 0;
    }
    free(tf.lines);
    return 1;
}

/* ----------------------------------------------------------------- object */

static int is_whole(double d) { return d == floor(d); }

int read_mesh(const char *path, Mesh *m)
{
    TextFile tf;
    int li, i, k, nv, nt, extra = 0;

    memset(m, 0, sizeof *m);
    if (!load_text(path, &tf))
        return 0;

    for (li = 0; li < tf.nlines; li++)
        if (tf.lines[li].bad) {
            fprintf(stderr, "error: %s line %d: not a number (comments are not part of the format)\n",
                    path, tf.lines[li].lineno);
            goto fail;
        }
    if (tf.nlines < 1) {
        fprintf(stderr, "error: %s: empty object file\n", path);
        goto fail;
    }
    if (tf.lines[0].count == 4) {
        fprintf(stderr, "error: %s: header of four numbers: this is a Movie.BYU file "
                "(parts, vertices, polygons, edges), not the course's .byu; not supported\n", path);
        goto fail;
    }
    if (tf.lines[0].count != 2 || !is_whole(tf.lines[0].v[0]) || !is_whole(tf.lines[0].v[1])) {
        fprintf(stderr, "error: %s: the first line must be \"vertices triangles\"\n", path);
        goto fail;
    }
    if (tf.nlines > 1 && tf.lines[1].count == 1) {
        fprintf(stderr, "error: %s: looks like a Bezier surface (degrees, evaluations, control "
                "points), not a triangle mesh; not supported\n", path);
        goto fail;
    }
    nv = (int)tf.lines[0].v[0];
    nt = (int)tf.lines[0].v[1];
    if (nv < 0 || nt < 0) {
        fprintf(stderr, "error: %s: negative counts in the header\n", path);
        goto fail;
    }
    m->nverts = nv;
    m->ntris = nt;
    m->verts = malloc((size_t)(nv + 1) * sizeof *m->verts);
    m->tris = malloc((size_t)(3 * nt + 1) * sizeof *m->tris);

    /* vertices: numbers read three at a time, whatever the lines */
    li = 1;
    k = 0;
    {
        double buf[3];
        int got = 0;
        while (k < nv) {
            if (li >= tf.nlines) {
                fprintf(stderr, "error: %s: the file ends after %d of %d vertices\n", path, k, nv);
                goto fail;
            }
            for (i = 0; i < tf.lines[li].count && k < nv; i++) {
                buf[got++] = tf.lines[li].v[i];
                if (got == 3) {
                    m->verts[k++] = vec3(buf[0], buf[1], buf[2]);
                    got = 0;
                }
            }
            if (i < tf.lines[li].count) {
                fprintf(stderr, "error: %s line %d: vertex line holds more numbers than expected\n",
                        path, tf.lines[li].lineno);
                goto fail;
            }
            li++;
        }
    }

    /* triangles: one per line, three 1-based indices */
    for (k = 0; k < nt; k++, li++) {
        Line *ln;
        if (li >= tf.nlines) {
            fprintf(stderr, "error: %s: the file ends after %d of %d triangles\n", path, k, nt);
            goto fail;
        }
        ln = &tf.lines[li];
        if (ln->count > 3) {
            fprintf(stderr, "error: %s line %d: a polygon of %d vertices; only triangles are supported\n",
                    path, ln->lineno, ln->count);
            goto fail;
        }
        if (ln->count < 3) {
            fprintf(stderr, "error: %s line %d: a triangle needs three indices\n", path, ln->lineno);
            goto fail;
        }
        for (i = 0; i < 3; i++) {
            double d = ln->v[i];
            if (!is_whole(d) || d < 1 || d > nv) {
                fprintf(stderr, "error: %s line %d: index %g is not a vertex (indices go from 1 to %d)\n",
                        path, ln->lineno, d, nv);
                goto fail;
            }
            m->tris[3 * k + i] = (int)d - 1;
        }
    }
    for (; li < tf.nlines; li++)
        extra += tf.lines[li].count;
    if (extra > 0)
        fprintf(stderr, "warning: %s: %d numbers after the declared %d vertices and %d triangles "
                "were ignored\n", path, extra, nv, nt);
    free(tf.lines);
    return 1;

fail:
    free(tf.lines);
    free_mesh(m);
    return 0;
}

void free_mesh(Mesh *m)
{
    free(m->verts);
    free(m->tris);
    m->verts = NULL;
    m->tris = NULL;
    m->nverts = m->ntris = 0;
}
