/*
 * main.c - command line of the seed 000 rasterizer.
 *
 *   stages --camera F --lighting F --object F [--size WxH] --output FILE.ppm [switches]
 *   stages --stages [switches]          (speaks the stage protocol on stdin/stdout)
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "raster.h"

static void usage(void)
{
    fprintf(stderr,
        "usage: stages --camera F --lighting F --object F [--size WxH] --output FILE.ppm [switches]\n"
        "       stages --stages [switches]\n"
        "switches (student mistakes, all off by default):\n"
        "  --light-in-world          the light is not moved to view coordinates\n"
        "  --round-screen            screen coordinates rounded instead of truncated\n"
        "  --normals-crossed         triangle normals (P3 - P1) x (P2 - P1)\n"
        "  --span-unit-steps         spans walked from the fractional left x, pixel floor(x)\n"
        "  --span-start-round        spans start at (int)(xl + 0.5)\n"
        "  --span-start-trunc        spans start at (int)xl\n"
        "  --span-open-end           spans stop before their right end (x < xr)\n"
        "  --span-open-start         spans start after their left end (x > xl)\n"
        "  --truncate-terms          each Phong term truncated to int before the sum\n"
        "  --epsilon E               the special cases tested against E instead of 0\n"
        "  --skip-small-triangles A  vertex normals skip triangles under A square pixels\n"
        "  --n-not-normalised-for-u  U = N x V with the N of the file\n"
        "  --double-free-crash       z-buffer rows one element short\n");
}

static int write_ppm(const char *path, const unsigned char *rgb, int width, int height)
{
    FILE *fp = fopen(path, "wb");
    if (fp == NULL) {
        fprintf(stderr, "error: cannot write %s\n", path);
        return 0;
    }
    fprintf(fp, "P6\n%d %d\n255\n", width, height);
    fwrite(rgb, 3, (size_t)width * height, fp);
    fclose(fp);
    return 1;
}

int main(int argc, char **argv)
{
    const char *camera_path = NULL, *lighting_path = NULL, *object_path = NULL;
    const char *output_path = NULL;
    int width = 640, height = 480, stages_mode = 0, i;
    Camera cam;
    Lighting light;
    Mesh mesh;
    unsigned char *rgb;

    memset(&g_opt, 0, sizeof g_opt);
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        int has_next = i + 1 < argc;

        if (strcmp(a, "--stages") == 0) stages_mode = 1;
        else if (strcmp(a, "--camera") == 0 && has_next) camera_path = argv[++i];
        else if (strcmp(a, "--lighting") == 0 && has_next) lighting_path = argv[++i];
        else if (strcmp(a, "--object") == 0 && has_next) object_path = argv[++i];
        else if (strcmp(a, "--output") == 0 && has_next) output_path = argv[++i];
        else if (strcmp(a, "--size") == 0 && has_next) {
            if (sscanf(argv[++i], "%dx%d", &width, &height) != 2 || width <= 0 || height <= 0) {
                fprintf(stderr, "error: --size wants WxH, e.g. 800x600\n");
                return 2;
            }
        }
        else if (strcmp(a, "--light-in-world") == 0) g_opt.light_in_world = 1;
        else if (strcmp(a, "--round-screen") == 0) g_opt.round_screen = 1;
        else if (strcmp(a, "--normals-crossed") == 0) g_opt.normals_crossed = 1;
        else if (strcmp(a, "--span-unit-steps") == 0) g_opt.span_unit_steps = 1;
        else if (strcmp(a, "--span-start-round") == 0) g_opt.span_start_round = 1;
        else if (strcmp(a, "--span-start-trunc") == 0) g_opt.span_start_trunc = 1;
        else if (strcmp(a, "--span-open-end") == 0) g_opt.span_open_end = 1;
        else if (strcmp(a, "--span-open-start") == 0) g_opt.span_open_start = 1;
        else if (strcmp(a, "--truncate-terms") == 0) g_opt.truncate_terms = 1;
        else if (strcmp(a, "--epsilon") == 0 && has_next) g_opt.epsilon = atof(argv[++i]);
        else if (strcmp(a, "--skip-small-triangles") == 0 && has_next) g_opt.skip_small_area = atof(argv[++i]);
        else if (strcmp(a, "--n-not-normalised-for-u") == 0) g_opt.n_not_normalised_for_u = 1;
        else if (strcmp(a, "--double-free-crash") == 0) g_opt.double_free_crash = 1;
        else if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage();
            return 0;
        } else {
            fprintf(stderr, "error: unknown or incomplete option %s\n", a);
            usage();
            return 2;
        }
    }

    if (g_opt.span_unit_steps + g_opt.span_open_start + g_opt.span_start_round +
        g_opt.span_start_trunc > 1)
        fprintf(stderr, "warning: several span starts given; the first of --span-unit-steps, "
                "--span-open-start, --span-start-round, --span-start-trunc is used\n");

    if (stages_mode)
        return run_stages();

    if (!camera_path || !lighting_path || !object_path || !output_path) {
        usage();
        return 2;
    }
    if (!read_camera(camera_path, &cam) || !read_lighting(lighting_path, &light) ||
        !read_mesh(object_path, &mesh))
        return 1;

    rgb = malloc((size_t)width * height * 3);
    if (rgb == NULL) {
        fprintf(stderr, "error: out of memory for a %dx%d image\n", width, height);
        return 1;
    }
    render_frame(&cam, &light, &mesh, width, height, rgb);
    if (!write_ppm(output_path, rgb, width, height))
        return 1;
    fprintf(stderr, "wrote %s (%dx%d, %d vertices, %d triangles)\n",
            output_path, width, height, mesh.nverts, mesh.ntris);
    free(rgb);
    free_mesh(&mesh);
    return 0;
}
