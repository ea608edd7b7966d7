/*
 * raster.h - seed 000 software rasterizer (course project), shared declarations.
 *
 * Files:
 *   pipeline.c  the seed's steps (basis, view, normals, projection, scan, z-buffer,
 *               Phong, whole frame)
 *   files.c     reading the course files (camera, lighting, .byu object)
 *   stages.c    the stage protocol adapter (--stages)
 *   main.c      command line, PPM output
 */
#ifndef RASTER_H
#define RASTER_H

#include <stddef.h>

typedef struct {
    double x, y, z;
} Vec3;

/* camera as read from the file (C, N, V not normalised) */
typedef struct {
    Vec3 C, N, V;
    double d, hx, hy;
} Camera;

/* orthonormal basis alfa = {U, V, N} */
typedef struct {
    Vec3 U, V, N;
} Basis;

/* lighting, as in the course's iluminacao.txt (Ia, Il on 0..255, Od on 0..1) */
typedef struct {
    Vec3 Pl;        /* light position (world, or view once converted) */
    double ka;
    Vec3 Ia;
    Vec3 kd;        /* the seed has one kd; kept per channel so the UFRPE Kd triple also loads */
    Vec3 Od;
    double ks;
    Vec3 Il;
    double n;
} Lighting;

typedef struct {
    int nverts, ntris;
    Vec3 *verts;    /* world coordinates */
    int *tris;      /* 3 * ntris, 0-based */
} Mesh;

/* the mistake switches, all off by default (see README.md) */
typedef struct {
    int light_in_world;
    int round_screen;
    int normals_crossed;
    int span_unit_steps;
    int span_start_round;
    int span_start_trunc;
    int span_open_end;
    int span_open_start;
    int truncate_terms;
    double epsilon;          /* 0: the seed's tests against 0 */
    double skip_small_area;  /* 0: off */
    int n_not_normalised_for_u;
    int double_free_crash;
} Options;

extern Options g_opt;

/* ---- vectors ---- */
Vec3 vec3(double x, double y, double z);
Vec3 vadd(Vec3 a, Vec3 b);
Vec3 vsub(Vec3 a, Vec3 b);
Vec3 vscale(Vec3 a, double s);
double vdot(Vec3 a, Vec3 b);
Vec3 vcross(Vec3 a, Vec3 b);
double vlength(Vec3 a);
Vec3 vnormalize(Vec3 a);   /* (0,0,0) stays (0,0,0) */

/* ---- pipeline.c: the seed's steps ---- */
Basis make_basis(Vec3 N, Vec3 V);
Vec3 world_to_view(const Basis *b, Vec3 C, Vec3 P);
void view_transform(const Basis *b, Vec3 C, const Vec3 *world, int n, Vec3 *view);
Vec3 light_to_view(const Basis *b, Vec3 C, Vec3 Pl);

void project_vertices(const Vec3 *view, int n, double d, double hx, double hy,
                      int width, int height, double *sx, double *sy);

double screen_area(const double *sx, const double *sy, int a, int b, int c);
void compute_normals(const Vec3 *view, int nverts, const int *tris, int ntris,
                     const double *sx, const double *sy,
                     Vec3 *tri_normals, Vec3 *vert_normals);

typedef void (*PlotFn)(void *ctx, int x, int y);
void scan_triangle(const double x[3], const double y[3], int width, int height,
                   PlotFn plot, void *ctx);

typedef struct {
    double z;       /* depth kept (view z), +infinity when empty */
    int t;          /* triangle whose fragment is kept (valid once z < +inf) */
} ZCell;

typedef struct {
    int width, height;
    ZCell **rows;   /* rows[y][x] */
} ZBuffer;

void zbuffer_init(ZBuffer *zb, int width, int height);
int zbuffer_test(ZBuffer *zb, int x, int y, double z, int t);
void zbuffer_free(ZBuffer *zb);

Vec3 phong(const Lighting *l, Vec3 P, Vec3 N);

void render_frame(const Camera *cam, const Lighting *light, const Mesh *mesh,
                  int width, int height, unsigned char *rgb);

/* ---- files.c ---- */
int read_camera(const char *path, Camera *cam);
int read_lighting(const char *path, Lighting *l);
int read_mesh(const char *path, Mesh *m);
void free_mesh(Mesh *m);

/* ---- stages.c ---- */
int run_stages(void);

#endif
