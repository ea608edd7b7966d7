/*
 * pipeline.c - the steps of seed 000, one function per step.
 *
 *   make_basis        Gram-Schmidt: N, V, U = N x V
 *   view_transform    [I]e,alfa * (P - C) for every vertex (and the light)
 *   project_vertices  view -> whole screen pixels
 *   compute_normals   triangle normals and vertex normals
 *   scan_triangle     scan conversion (one span per row)
 *   zbuffer_*         the z-buffer, starting at +infinity
 *   phong             Phong at a point with the seed's special cases
 *   render_frame      all of it, into an RGB image
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raster.h"

Options g_opt;

/* ------------------------------------------------------------------ vectors */

Vec3 vec3(double x, double y, double z)
{
    Vec3 v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

Vec3 vadd(Vec3 a, Vec3 b) { return vec3(a.x + b.x, a.y + b.y, a.z + b.z); }
Vec3 vsub(Vec3 a, Vec3 b) { return vec3(a.x - b.x, a.y - b.y, a.z - b.z); }
Vec3 vscale(Vec3 a, double s) { return vec3(a.x * s, a.y * s, a.z * s); }
double vdot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

Vec3 vcross(Vec3 a, Vec3 b)
{
    return vec3(a.y * b.z - a.z * b.y,
                a.z * b.x - a.x * b.z,
                a.x * b.y - a.y * b.x);
}

double vlength(Vec3 a) { return sqrt(vdot(a, a)); }

Vec3 vnormalize(Vec3 a)
{
    double len = vlength(a);
    if (len == 0)
        return vec3(0, 0, 0);
    return vec3(a.x / len, a.y / len, a.z / len);
}

/* ---------------------------------------------------- camera basis (alfa) */

/*
 * Normalizar N; V = V - proj_N(V); normalizar V; U = N x V.
 */
Basis make_basis(Vec3 N_file, Vec3 V_file)
{
    Basis b;
    Vec3 N = vnormalize(N_file);
    Vec3 V = vsub(V_file, vscale(N, vdot(V_file, N)));   /* Gram-Schmidt */
    V = vnormalize(V);

    if (g_opt.n_not_normalised_for_u)
        b.U = vcross(N_file, V);    /* the N read from the file, not the unit one */
    else
        b.U = vcross(N, V);
    b.V = V;
    b.N = N;
    return b;
}

/* [I]e,alfa * (P - C): the rows of the matrix are U, V, N */
Vec3 world_to_view(const Basis *b, Vec3 C, Vec3 P)
{
    Vec3 d = vsub(P, C);
    return vec3(vdot(b->U, d), vdot(b->V, d), vdot(b->N, d));
}

void view_transform(const Basis *b, Vec3 C, const Vec3 *world, int n, Vec3 *view)
{
    int i;
    for (i = 0; i < n; i++)
        view[i] = world_to_view(b, C, world[i]);
}

/* Pl_vista = [I]e,alfa * (Pl - C) */
Vec3 light_to_view(const Basis *b, Vec3 C, Vec3 Pl)
{
    if (g_opt.light_in_world)
        return Pl;     /* the light stays where the file put it */
    return world_to_view(b, C, Pl);
}

/* ------------------------------------------------------------ projection */

static int to_pixel(double v)
{
    /* keep the cast defined for points far off the screen */
    if (v > 1e9)
        v = 1e9;
    if (v < -1e9)
        v = -1e9;
    if (g_opt.round_screen)
        return (int)(v + 0.5);
    return (int)v;
}

/*
 * P_tela = ((d/hx) * (x/z), (d/hy) * (y/z)), then to the window:
 *   x = (int)((P_tela.x + 1) * width / 2)
 *   y = (int)((1 - P_tela.y) * height / 2)
 * The results are whole pixels, kept in doubles.
 */
void project_vertices(const Vec3 *view, int n, double d, double hx, double hy,
                      int width, int height, double *sx, double *sy)
{
    int i;
    static int warned = 0;
    for (i = 0; i < n; i++) {
        Vec3 p = view[i];
        double px, py;
        if (p.z <= 0 && !warned) {
            fprintf(stderr, "warning: vertex %d is not in front of the camera (z = %g); "
                    "seed 000 divides by z anyway\n", i, p.z);
            warned = 1;
        }
        px = (d / hx) * (p.x / p.z);
        py = (d / hy) * (p.y / p.z);
        if (isnan(px))
            px = 0;
        if (isnan(py))
            py = 0;
        sx[i] = to_pixel((px + 1) * width / 2);
        sy[i] = to_pixel((1 - py) * height / 2);
    }
}

/* ---------------------------------------------------------------- normals */

/* area of a triangle on the screen, in square pixels */
double screen_area(const double *sx, const double *sy, int a, int b, int c)
{
    double area2 = (sx[b] - sx[a]) * (sy[c] - sy[a]) - (sx[c] - sx[a]) * (sy[b] - sy[a]);
    return fabs(area2) / 2;
}

/*
 * Triangle normal (P2 - P1) x (P3 - P1), normalised; summed into each of its
 * three vertices; then every vertex normal normalised.
 * sx, sy (the screen points) are only used by --skip-small-triangles and may be NULL.
 */
void compute_normals(const Vec3 *view, int nverts, const int *tris, int ntris,
                     const double *sx, const double *sy,
                     Vec3 *tri_normals, Vec3 *vert_normals)
{
    int i, t;

    for (i = 0; i < nverts; i++)
        vert_normals[i] = vec3(0, 0, 0);

    for (t = 0; t < ntris; t++) {
        int a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
        Vec3 e1 = vsub(view[b], view[a]);
        Vec3 e2 = vsub(view[c], view[a]);
        Vec3 n;

        if (g_opt.normals_crossed)
            n = vcross(e2, e1);
        else
            n = vcross(e1, e2);
        n = vnormalize(n);
        tri_normals[t] = n;

        /* degenerate triangles on the screen are left out of the vertex normals */
        if (g_opt.skip_small_area > 0 && sx != NULL &&
            screen_area(sx, sy, a, b, c) < g_opt.skip_small_area)
            continue;

        vert_normals[a] = vadd(vert_normals[a], n);
        vert_normals[b] = vadd(vert_normals[b], n);
        vert_normals[c] = vadd(vert_normals[c], n);
    }

    for (i = 0; i < nverts; i++)
        vert_normals[i] = vnormalize(vert_normals[i]);
}

/* ------------------------------------------------------- scan conversion */

/*
 * One span of row y, from the left edge xl to the right edge xr (fractional).
 * A pixel x belongs to the triangle when xl <= x <= xr.
 */
static void draw_span(int y, double xl, double xr, int width, PlotFn plot, void *ctx)
{
    double x;

    /* where the walk starts */
    if (g_opt.span_unit_steps)
        x = xl;                      /* the edge itself, pixel floor(x) */
    else if (g_opt.span_open_start)
        x = floor(xl) + 1;           /* first pixel after xl */
    else if (g_opt.span_start_round)
        x = (int)(xl + 0.5);
    else if (g_opt.span_start_trunc)
        x = (int)xl;
    else
        x = ceil(xl);                /* first pixel on or after xl */

    /* no need to walk the part left of the screen */
    if (x < 0)
        x += floor(-x);

    for (; g_opt.span_open_end ? x < xr : x <= xr; x += 1) {
        int px = (int)floor(x);
        if (px >= width)
            break;
        if (px >= 0)
            plot(ctx, px, y);
    }
}

/*
 * Scan conversion of one triangle given by its screen vertices.
 * For each row y between the top and the bottom vertex, the row crosses the
 * triangle's edges; the leftmost and rightmost crossings bound the span.
 * Only rows 0..height-1 are visited; draw_span keeps x inside 0..width-1.
 */
void scan_triangle(const double x[3], const double y[3], int width, int height,
                   PlotFn plot, void *ctx)
{
    double area2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    double ymin, ymax, ys, ye;
    int row, yfirst, ylast, e;

    if (area2 == 0 || isnan(area2))
        return;     /* zero area: covers nothing */

    ymin = fmin(y[0], fmin(y[1], y[2]));
    ymax = fmax(y[0], fmax(y[1], y[2]));
    ys = ceil(ymin);
    ye = floor(ymax);
    if (ys < 0)
        ys = 0;
    if (ye > height - 1)
        ye = height - 1;
    if (ys > ye)
        return;
    yfirst = (int)ys;
    ylast = (int)ye;

    for (row = yfirst; row <= ylast; row++) {
        double xl = INFINITY, xr = -INFINITY;

        for (e = 0; e < 3; e++) {
            int a = e, b = (e + 1) % 3;
            double xi;

            if (y[a] == y[b]) {
                /* horizontal edge: the whole edge is on this row (or not at all) */
                if (y[a] == row) {
                    xl = fmin(xl, fmin(x[a], x[b]));
                    xr = fmax(xr, fmax(x[a], x[b]));
                }
                continue;
            }
            if (row < fmin(y[a], y[b]) || row > fmax(y[a], y[b]))
                continue;
            xi = x[a] + (row - y[a]) * (x[b] - x[a]) / (y[b] - y[a]);
            xl = fmin(xl, xi);
            xr = fmax(xr, xi);
        }
        if (xl > xr)
            continue;
        draw_span(row, xl, xr, width, plot, ctx);
    }
}

/* ---------------------------------------------------------------- z-buffer */

void zbuffer_init(ZBuffer *zb, int width, int height)
{
    int x, y;
    size_t row_len = (size_t)width;

    if (g_opt.double_free_crash)
        row_len = (size_t)width - 1;   /* "x goes from 0 to width - 1" */

    zb->width = width;
    zb->height = height;
    zb->rows = malloc((size_t)height * sizeof *zb->rows);
    if (zb->rows == NULL) {
        fprintf(stderr, "out of memory (z-buffer)\n");
        exit(1);
    }
    for (y = 0; y < height; y++) {
        zb->rows[y] = malloc(row_len * sizeof(ZCell));
        if (zb->rows[y] == NULL) {
            fprintf(stderr, "out of memory (z-buffer)\n");
            exit(1);
        }
        for (x = 0; x < width; x++)
            zb->rows[y][x].z = INFINITY;   /* +infinito; t is set with the first fragment */
    }
}

/*
 * Se P'.z < z-buffer[x][y] (checking the array's limits): keep it.
 * Returns 1 when the fragment is kept.
 */
int zbuffer_test(ZBuffer *zb, int x, int y, double z, int t)
{
    ZCell *cell;
    if (x < 0 || x >= zb->width || y < 0 || y >= zb->height)
        return 0;
    cell = &zb->rows[y][x];
    if (z < cell->z) {
        cell->z = z;
        cell->t = t;
        return 1;
    }
    return 0;
}

void zbuffer_free(ZBuffer *zb)
{
    int y;
    for (y = 0; y < zb->height; y++)
        free(zb->rows[y]);
    free(zb->rows);
    zb->rows = NULL;
}

/* ------------------------------------------------------------------ Phong */

/*
 * Phong at P' (view coordinates) with normal N:
 *   V = -P', L = Pl - P', N, V, L normalised
 *   V.N < 0: N = -N
 *   N.L < 0: no diffuse nor specular
 *   R = 2 (N.L) N - L, normalised; R.V < 0: no specular
 *   I = Ia ka + Il Od kd (N.L) + Il ks (R.V)^n, each channel at most 255.
 * (--epsilon E tests against E instead of 0.)
 */
Vec3 phong(const Lighting *l, Vec3 P, Vec3 N)
{
    double eps = g_opt.epsilon;
    Vec3 V = vnormalize(vscale(P, -1));
    Vec3 L = vnormalize(vsub(l->Pl, P));
    Vec3 amb, dif = vec3(0, 0, 0), spe = vec3(0, 0, 0), I;
    double NL;

    N = vnormalize(N);
    if (vdot(V, N) < eps)
        N = vscale(N, -1);

    amb = vec3(l->Ia.x * l->ka, l->Ia.y * l->ka, l->Ia.z * l->ka);

    NL = vdot(N, L);
    if (!(NL < eps)) {
        Vec3 R;
        double RV;

        dif = vec3(l->Il.x * l->Od.x * l->kd.x * NL,
                   l->Il.y * l->Od.y * l->kd.y * NL,
                   l->Il.z * l->Od.z * l->kd.z * NL);

        R = vsub(vscale(N, 2 * NL), L);
        R = vnormalize(R);
        RV = vdot(R, V);
        if (!(RV < eps)) {
            double s = l->ks * pow(RV, l->n);
            spe = vec3(l->Il.x * s, l->Il.y * s, l->Il.z * s);
        }
    }

    if (g_opt.truncate_terms) {
        amb = vec3((int)amb.x, (int)amb.y, (int)amb.z);
        dif = vec3((int)dif.x, (int)dif.y, (int)dif.z);
        spe = vec3((int)spe.x, (int)spe.y, (int)spe.z);
    }

    I = vadd(vadd(amb, dif), spe);
    if (I.x > 255) I.x = 255;
    if (I.y > 255) I.y = 255;
    if (I.z > 255) I.z = 255;
    return I;
}

/* ------------------------------------------------------------ whole frame */

typedef struct {
    const Vec3 *view;           /* vertices in view coordinates */
    const Vec3 *vert_normals;
    const Lighting *light;      /* Pl already in view coordinates */
    ZBuffer *zb;
    unsigned char *rgb;
    int width;
    int t;                      /* current triangle */
    int v[3];                   /* its vertex indices */
    double x[3], y[3];          /* its screen vertices */
} FrameCtx;

static unsigned char to_byte(double c)
{
    if (c > 255)
        c = 255;
    if (c < 0 || isnan(c))
        c = 0;
    return (unsigned char)(int)c;
}

/* one pixel P of the current triangle: barycentrics, P', z-buffer, Phong */
static void shade_pixel(void *data, int px, int py)
{
    FrameCtx *f = data;
    double x1 = f->x[0], y1 = f->y[0], x2 = f->x[1], y2 = f->y[1], x3 = f->x[2], y3 = f->y[2];
    double den = (y2 - y3) * (x1 - x3) + (x3 - x2) * (y1 - y3);
    double alfa, beta, gama;
    Vec3 P, N, I;
    unsigned char *out;

    if (den == 0)
        return;
    /* P = alfa*v1 + beta*v2 + gama*v3 with alfa + beta + gama = 1 */
    alfa = ((y2 - y3) * (px - x3) + (x3 - x2) * (py - y3)) / den;
    beta = ((y3 - y1) * (px - x3) + (x1 - x3) * (py - y3)) / den;
    gama = 1 - alfa - beta;

    P = vadd(vadd(vscale(f->view[f->v[0]], alfa), vscale(f->view[f->v[1]], beta)),
             vscale(f->view[f->v[2]], gama));

    if (!zbuffer_test(f->zb, px, py, P.z, f->t))
        return;

    N = vadd(vadd(vscale(f->vert_normals[f->v[0]], alfa),
                  vscale(f->vert_normals[f->v[1]], beta)),
             vscale(f->vert_normals[f->v[2]], gama));
    I = phong(f->light, P, N);

    out = f->rgb + 3 * ((size_t)py * f->width + px);
    out[0] = to_byte(I.x);
    out[1] = to_byte(I.y);
    out[2] = to_byte(I.z);
}

/*
 * Seed 000 from the files' values to an RGB image (row 0 at the top,
 * background black). Every triangle is drawn: none culled, none clipped.
 */
void render_frame(const Camera *cam, const Lighting *light, const Mesh *mesh,
                  int width, int height, unsigned char *rgb)
{
    Basis b = make_basis(cam->N, cam->V);
    Lighting lv = *light;
    Vec3 *view = malloc((size_t)(mesh->nverts + 1) * sizeof *view);
    Vec3 *tri_n = malloc((size_t)(mesh->ntris + 1) * sizeof *tri_n);
    Vec3 *vert_n = malloc((size_t)(mesh->nverts + 1) * sizeof *vert_n);
    double *sx = malloc((size_t)(mesh->nverts + 1) * sizeof *sx);
    double *sy = malloc((size_t)(mesh->nverts + 1) * sizeof *sy);
    ZBuffer zb;
    FrameCtx f;
    int t, k;

    if (!view || !tri_n || !vert_n || !sx || !sy) {
        fprintf(stderr, "out of memory\n");
        exit(1);
    }

    view_transform(&b, cam->C, mesh->verts, mesh->nverts, view);
    lv.Pl = light_to_view(&b, cam->C, light->Pl);

    /* projected before the normals: the degenerate-triangle filter needs the screen */
    project_vertices(view, mesh->nverts, cam->d, cam->hx, cam->hy, width, height, sx, sy);
    compute_normals(view, mesh->nverts, mesh->tris, mesh->ntris, sx, sy, tri_n, vert_n);

    memset(rgb, 0, (size_t)width * height * 3);
    zbuffer_init(&zb, width, height);

    f.view = view;
    f.vert_normals = vert_n;
    f.light = &lv;
    f.zb = &zb;
    f.rgb = rgb;
    f.width = width;
    for (t = 0; t < mesh->ntris; t++) {
        f.t = t;
        for (k = 0; k < 3; k++) {
            f.v[k] = mesh->tris[3 * t + k];
            f.x[k] = sx[f.v[k]];
            f.y[k] = sy[f.v[k]];
        }
        scan_triangle(f.x, f.y, width, height, shade_pixel, &f);
    }

    zbuffer_free(&zb);
    free(view);
    free(tri_n);
    free(vert_n);
    free(sx);
    free(sy);
}
