/*
 * stages.c - the stage protocol (version 1) around the renderer's own functions.
 *
 * RasterLab writes a request (the stage's name, its records, "end") on standard
 * input; we answer with our records and "end" on standard output. Every stage
 * calls the same functions the renderer uses (pipeline.c), with the same
 * switches (g_opt), so a mistake shows in the stage answers as in the image.
 * Debugging output goes to standard error only.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raster.h"

#define MAX_RECORDS 32
#define MAX_VALS 8

typedef struct {
    char name[32];
    int nvals;
    double vals[MAX_VALS];
    int count;          /* list records: number of rows, else -1 */
    double *rows;       /* count rows of MAX_VALS numbers */
    int *row_len;       /* numbers on each row */
} Record;

typedef struct {
    char stage[32];
    int n;
    Record rec[MAX_RECORDS];
} Request;

/* the last camera and screen size this session was told about (see README) */
static int have_screen = 0;
static double last_d, last_hx, last_hy;
static int last_width, last_height;

/* ------------------------------------------------------------- reading */

static char *line_buf = NULL;
static size_t line_cap = 0;

/* one line without its "\n" or "\r\n"; NULL at the end of the input */
static char *read_line(void)
{
    size_t len = 0;
    int c;

    if (line_buf == NULL) {
        line_cap = 256;
        line_buf = malloc(line_cap);
    }
    while ((c = getchar()) != EOF && c != '\n') {
        if (len + 1 >= line_cap) {
            line_cap *= 2;
            line_buf = realloc(line_buf, line_cap);
        }
        line_buf[len++] = (char)c;
    }
    if (c == EOF && len == 0)
        return NULL;
    if (len > 0 && line_buf[len - 1] == '\r')
        len--;
    line_buf[len] = '\0';
    return line_buf;
}

/* reads up to max numbers from a string; returns how many there were */
static int parse_numbers(char *s, double *vals, int max)
{
    int n = 0;
    char *end;

    for (;;) {
        double d;
        while (*s == ' ' || *s == '\t')
            s++;
        if (*s == '\0')
            break;
        d = strtod(s, &end);
        if (end == s) {
            fprintf(stderr, "stages: not a number: %s\n", s);
            break;
        }
        if (n < max)
            vals[n] = d;
        n++;
        s = end;
    }
    return n;
}

/* splits a line into its name and numbers; returns the count of numbers */
static int split_line(char *line, char *name, size_t name_size, double *vals, int max)
{
    size_t len = 0;

    while (*line == ' ' || *line == '\t')
        line++;
    while (line[len] && line[len] != ' ' && line[len] != '\t')
        len++;
    if (len >= name_size)
        len = name_size - 1;
    memcpy(name, line, len);
    name[len] = '\0';
    while (*line && *line != ' ' && *line != '\t')
        line++;
    return parse_numbers(line, vals, max);
}

static int is_list(const char *name)
{
    return strcmp(name, "vertices") == 0 || strcmp(name, "triangles") == 0 ||
           strcmp(name, "fragments") == 0 || strcmp(name, "samples") == 0;
}

static void free_request(Request *req)
{
    int i;
    for (i = 0; i < req->n; i++) {
        free(req->rec[i].rows);
        free(req->rec[i].row_len);
    }
    req->n = 0;
}

/* reads the records of a request up to "end"; 0 when the input ended */
static int read_request(Request *req)
{
    char *line;

    req->n = 0;
    for (;;) {
        Record r;
        char name[32];
        double vals[MAX_VALS];
        int nv, k;

        line = read_line();
        if (line == NULL)
            return 0;
        nv = split_line(line, name, sizeof name, vals, MAX_VALS);
        if (name[0] == '\0')
            continue;
        if (strcmp(name, "end") == 0)
            return 1;

        memset(&r, 0, sizeof r);
        strcpy(r.name, name);
        r.nvals = nv < MAX_VALS ? nv : MAX_VALS;
        memcpy(r.vals, vals, r.nvals * sizeof(double));
        r.count = -1;

        if (is_list(name)) {
            r.count = nv > 0 ? (int)vals[0] : 0;
            r.rows = malloc((size_t)(r.count + 1) * MAX_VALS * sizeof(double));
            r.row_len = malloc((size_t)(r.count + 1) * sizeof(int));
            for (k = 0; k < r.count; k++) {
                line = read_line();
                if (line == NULL)
                    return 0;
                r.row_len[k] = parse_numbers(line, r.rows + (size_t)k * MAX_VALS, MAX_VALS);
            }
        }
        if (req->n < MAX_RECORDS)
            req->rec[req->n++] = r;
    }
}

static Record *get(Request *req, const char *name)
{
    int i;
    for (i = 0; i < req->n; i++)
        if (strcmp(req->rec[i].name, name) == 0)
            return &req->rec[i];
    fprintf(stderr, "stages: request %s has no record %s\n", req->stage, name);
    return NULL;
}

static Vec3 get_vec(Request *req, const char *name)
{
    Record *r = get(req, name);
    if (r == NULL || r->nvals < 3)
        return vec3(0, 0, 0);
    return vec3(r->vals[0], r->vals[1], r->vals[2]);
}

static double get_num(Request *req, const char *name, int i)
{
    Record *r = get(req, name);
    if (r == NULL || r->nvals <= i)
        return 0;
    return r->vals[i];
}

/* the rows of a list record as points */
static Vec3 *get_points(Request *req, const char *name, int *n)
{
    Record *r = get(req, name);
    Vec3 *p;
    int i;
    *n = r ? r->count : 0;
    p = malloc((size_t)(*n + 1) * sizeof *p);
    for (i = 0; i < *n; i++) {
        double *row = r->rows + (size_t)i * MAX_VALS;
        p[i] = vec3(row[0], row[1], row[2]);
    }
    return p;
}

static int *get_indices(Request *req, const char *name, int *n)
{
    Record *r = get(req, name);
    int *t;
    int i, k;
    *n = r ? r->count : 0;
    t = malloc((size_t)(3 * *n + 1) * sizeof *t);
    for (i = 0; i < *n; i++)
        for (k = 0; k < 3; k++)
            t[3 * i + k] = (int)r->rows[(size_t)i * MAX_VALS + k];
    return t;
}

/* ------------------------------------------------------------- writing */

static void put_vec(const char *name, Vec3 v)
{
    if (name)
        printf("%s %.17g %.17g %.17g\n", name, v.x, v.y, v.z);
    else
        printf("%.17g %.17g %.17g\n", v.x, v.y, v.z);
}

static void end_answer(void)
{
    printf("end\n");
    fflush(stdout);
}

/* ------------------------------------------------------------- stages */

static void stage_basis(Request *req)
{
    Basis b = make_basis(get_vec(req, "N"), get_vec(req, "V"));
    put_vec("U", b.U);
    put_vec("V", b.V);
    put_vec("N", b.N);
    end_answer();
}

static void stage_view(Request *req)
{
    Basis b;
    Vec3 C = get_vec(req, "C");
    Vec3 *world, *view;
    int n, i;

    b.U = get_vec(req, "U");
    b.V = get_vec(req, "V");
    b.N = get_vec(req, "N");
    world = get_points(req, "vertices", &n);
    view = malloc((size_t)(n + 1) * sizeof *view);
    view_transform(&b, C, world, n, view);

    put_vec("light", light_to_view(&b, C, get_vec(req, "light")));
    printf("vertices %d\n", n);
    for (i = 0; i < n; i++)
        put_vec(NULL, view[i]);
    end_answer();
    free(world);
    free(view);
}

static void stage_normals(Request *req)
{
    int n, m, i;
    Vec3 *view = get_points(req, "vertices", &n);
    int *tris = get_indices(req, "triangles", &m);
    Vec3 *tri_n = malloc((size_t)(m + 1) * sizeof *tri_n);
    Vec3 *vert_n = malloc((size_t)(n + 1) * sizeof *vert_n);
    double *sx = NULL, *sy = NULL;

    /* the filter of --skip-small-triangles needs the screen, which this request
       does not carry: use the last camera and size we were given */
    if (g_opt.skip_small_area > 0) {
        if (have_screen) {
            sx = malloc((size_t)(n + 1) * sizeof *sx);
            sy = malloc((size_t)(n + 1) * sizeof *sy);
            project_vertices(view, n, last_d, last_hx, last_hy, last_width, last_height, sx, sy);
        } else {
            fprintf(stderr, "stages: normals: no camera seen yet, small triangles not filtered\n");
        }
    }
    compute_normals(view, n, tris, m, sx, sy, tri_n, vert_n);

    printf("triangle-normals %d\n", m);
    for (i = 0; i < m; i++)
        put_vec(NULL, tri_n[i]);
    printf("vertex-normals %d\n", n);
    for (i = 0; i < n; i++)
        put_vec(NULL, vert_n[i]);
    end_answer();
    free(view);
    free(tris);
    free(tri_n);
    free(vert_n);
    free(sx);
    free(sy);
}

static void remember_screen(double d, double hx, double hy, int width, int height)
{
    have_screen = 1;
    last_d = d;
    last_hx = hx;
    last_hy = hy;
    last_width = width;
    last_height = height;
}

static void stage_projection(Request *req)
{
    double d = get_num(req, "camera", 0), hx = get_num(req, "camera", 1), hy = get_num(req, "camera", 2);
    int width = (int)get_num(req, "size", 0), height = (int)get_num(req, "size", 1);
    int n, i;
    Vec3 *view = get_points(req, "vertices", &n);
    double *sx = malloc((size_t)(n + 1) * sizeof *sx);
    double *sy = malloc((size_t)(n + 1) * sizeof *sy);

    remember_screen(d, hx, hy, width, height);
    project_vertices(view, n, d, hx, hy, width, height, sx, sy);
    printf("screen %d\n", n);
    for (i = 0; i < n; i++)
        printf("%d %d\n", (int)sx[i], (int)sy[i]);
    end_answer();
    free(view);
    free(sx);
    free(sy);
}

/* spans of the scan stage: the plot callback grows the current span */
typedef struct {
    int t, y, first, last;
} Span;

typedef struct {
    Span *spans;
    int n, cap;
    int t;
} SpanList;

static void add_pixel(void *data, int x, int y)
{
    SpanList *sl = data;
    if (sl->n > 0) {
        Span *s = &sl->spans[sl->n - 1];
        if (s->t == sl->t && s->y == y && s->last + 1 == x) {
            s->last = x;
            return;
        }
    }
    if (sl->n == sl->cap) {
        sl->cap = sl->cap ? 2 * sl->cap : 256;
        sl->spans = realloc(sl->spans, (size_t)sl->cap * sizeof *sl->spans);
    }
    sl->spans[sl->n].t = sl->t;
    sl->spans[sl->n].y = y;
    sl->spans[sl->n].first = x;
    sl->spans[sl->n].last = x;
    sl->n++;
}

static void stage_scan(Request *req)
{
    int width = (int)get_num(req, "size", 0), height = (int)get_num(req, "size", 1);
    Record *r = get(req, "triangles");
    SpanList sl;
    int t, k, m = r ? r->count : 0;

    memset(&sl, 0, sizeof sl);
    for (t = 0; t < m; t++) {
        double *row = r->rows + (size_t)t * MAX_VALS;
        double x[3], y[3];
        for (k = 0; k < 3; k++) {
            x[k] = row[2 * k];
            y[k] = row[2 * k + 1];
        }
        sl.t = t;
        scan_triangle(x, y, width, height, add_pixel, &sl);
    }
    printf("spans %d\n", sl.n);
    for (k = 0; k < sl.n; k++)
        printf("%d %d %d %d\n", sl.spans[k].t, sl.spans[k].y, sl.spans[k].first, sl.spans[k].last);
    end_answer();
    free(sl.spans);
}

typedef struct {
    int x, y, t;
    double z;
} Pixel;

static void stage_zbuffer(Request *req)
{
    int width = (int)get_num(req, "size", 0), height = (int)get_num(req, "size", 1);
    Record *r = get(req, "fragments");
    ZBuffer zb;
    Pixel *pix;
    int i, x, y, np = 0, k = r ? r->count : 0;

    zbuffer_init(&zb, width, height);
    for (i = 0; i < k; i++) {
        double *row = r->rows + (size_t)i * MAX_VALS;
        zbuffer_test(&zb, (int)row[1], (int)row[2], row[3], (int)row[0]);
    }

    /* every pixel some fragment reached */
    pix = malloc(((size_t)width * height + 1) * sizeof *pix);
    for (y = 0; y < height; y++)
        for (x = 0; x < width; x++)
            if (zb.rows[y][x].z < INFINITY) {
                pix[np].x = x;
                pix[np].y = y;
                pix[np].t = zb.rows[y][x].t;
                pix[np].z = zb.rows[y][x].z;
                np++;
            }
    zbuffer_free(&zb);

    printf("pixels %d\n", np);
    for (i = 0; i < np; i++)
        printf("%d %d %d %.17g\n", pix[i].x, pix[i].y, pix[i].t, pix[i].z);
    end_answer();
    free(pix);
}

static void read_lighting_records(Request *req, Lighting *l)
{
    double kd = get_num(req, "kd", 0);
    l->Pl = get_vec(req, "light");
    l->Ia = get_vec(req, "Ia");
    l->Il = get_vec(req, "Il");
    l->ka = get_num(req, "ka", 0);
    l->kd = vec3(kd, kd, kd);
    l->Od = get_vec(req, "Od");
    l->ks = get_num(req, "ks", 0);
    l->n = get_num(req, "n", 0);
}

static void stage_lighting(Request *req)
{
    Lighting l;
    Record *r = get(req, "samples");
    int i, k = r ? r->count : 0;

    read_lighting_records(req, &l);     /* Pl is already in view coordinates */
    printf("colours %d\n", k);
    for (i = 0; i < k; i++) {
        double *row = r->rows + (size_t)i * MAX_VALS;
        Vec3 I = phong(&l, vec3(row[0], row[1], row[2]), vec3(row[3], row[4], row[5]));
        put_vec(NULL, I);
    }
    end_answer();
}

static void stage_frame(Request *req)
{
    int width = (int)get_num(req, "size", 0), height = (int)get_num(req, "size", 1);
    Camera cam;
    Lighting l;
    Mesh mesh;
    unsigned char *rgb;
    char *line;
    int x, y;

    cam.C = get_vec(req, "C");
    cam.N = get_vec(req, "N");
    cam.V = get_vec(req, "V");
    cam.d = get_num(req, "camera", 0);
    cam.hx = get_num(req, "camera", 1);
    cam.hy = get_num(req, "camera", 2);
    read_lighting_records(req, &l);     /* here the light is in the world */
    mesh.verts = get_points(req, "vertices", &mesh.nverts);
    mesh.tris = get_indices(req, "triangles", &mesh.ntris);
    remember_screen(cam.d, cam.hx, cam.hy, width, height);

    rgb = malloc((size_t)width * height * 3 + 1);
    render_frame(&cam, &l, &mesh, width, height, rgb);

    printf("image %d %d\n", width, height);
    line = malloc((size_t)width * 12 + 2);
    for (y = 0; y < height; y++) {
        char *p = line;
        for (x = 0; x < 3 * width; x++)
            p += sprintf(p, x ? " %d" : "%d", rgb[(size_t)y * width * 3 + x]);
        *p++ = '\n';
        *p = '\0';
        fputs(line, stdout);
    }
    end_answer();
    free(line);
    free(rgb);
    free_mesh(&mesh);
}

/* ------------------------------------------------------------- session */

int run_stages(void)
{
    char *line = read_line();
    Request req;

    if (line == NULL)
        return 1;
    if (strncmp(line, "rasterlab", 9) != 0)
        fprintf(stderr, "stages: unexpected greeting \"%s\"\n", line);
    printf("speaks 1\n");
    fflush(stdout);

    req.n = 0;
    for (;;) {
        char name[32];
        double dummy[1];

        line = read_line();
        if (line == NULL)
            break;
        split_line(line, name, sizeof name, dummy, 0);
        if (name[0] == '\0')
            continue;
        if (strcmp(name, "bye") == 0)
            break;
        strcpy(req.stage, name);
        if (!read_request(&req)) {
            free_request(&req);
            break;
        }

        if (strcmp(name, "basis") == 0)
            stage_basis(&req);
        else if (strcmp(name, "view") == 0)
            stage_view(&req);
        else if (strcmp(name, "normals") == 0)
            stage_normals(&req);
        else if (strcmp(name, "projection") == 0)
            stage_projection(&req);
        else if (strcmp(name, "scan") == 0)
            stage_scan(&req);
        else if (strcmp(name, "zbuffer") == 0)
            stage_zbuffer(&req);
        else if (strcmp(name, "lighting") == 0)
            stage_lighting(&req);
        else if (strcmp(name, "frame") == 0)
            stage_frame(&req);
        else {
            printf("unsupported\n");
            fflush(stdout);
        }
        free_request(&req);
    }
    free(line_buf);
    return 0;
}
