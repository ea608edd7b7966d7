#!/usr/bin/env python3
"""Tests of the student rasterizer: values computed by hand on tiny scenes,
and every mistake switch changing the image of a small scene.

    python3 -m unittest test_rasterizer      (from this folder)
"""

import os
import tempfile
import unittest

import pngdiff
import rasterizer as r


def options(*switches):
    """Parsed options as the command line gives them, files not read."""
    return r.make_parser().parse_args(
        ["--camera", "c", "--lighting", "l", "--object", "o",
         "--output", "out.png", *switches])


# One triangle facing the camera.  C at the origin looking down +z with V up:
# U = N x V = (0,0,1) x (0,1,0) = (-1, 0, 0), so view = (-x, y, z) and the
# world vertices below are, in view space, (-4,-4,8), (4,-4,8), (0,4,8).
# d = hx = hy = 1 on 100x100: x/z = -0.5 gives (int)(0.5 * 50) = 25, etc.
TINY_CAMERA = {"C": (0.0, 0.0, 0.0), "N": (0.0, 0.0, 1.0),
               "V": (0.0, 1.0, 0.0), "d": 1.0, "hx": 1.0, "hy": 1.0}
TINY_POINTS = [(4.0, -4.0, 8.0), (-4.0, -4.0, 8.0), (0.0, 4.0, 8.0)]
TINY_LIGHT = {"Pl": (0.0, 0.0, 0.0), "ka": 0.5, "Ia": (20.0, 40.0, 60.0),
              "kd": 0.5, "Od": (1.0, 0.5, 0.25), "ks": 0.25,
              "Il": (200.0, 100.0, 40.0), "n": 3.0}


class HandComputed(unittest.TestCase):
    def test_gram_schmidt_basis(self):
        # N = (0,0,2) -> (0,0,1); V = (0,3,4) - 4 N = (0,3,0) -> (0,1,0);
        # U = N x V = (-1, 0, 0).
        U, V, N = r.camera_basis((0.0, 0.0, 2.0), (0.0, 3.0, 4.0), options())
        self.assertEqual(N, (0.0, 0.0, 1.0))
        self.assertEqual(V, (0.0, 1.0, 0.0))
        self.assertEqual(U, (-1.0, 0.0, 0.0))

    def test_u_v_cross_n_mirrors_u(self):
        U, _, _ = r.camera_basis((0.0, 0.0, 2.0), (0.0, 3.0, 4.0),
                                 options("--u-v-cross-n"))
        self.assertEqual(U, (1.0, 0.0, 0.0))

    def test_view_point(self):
        # P - C = (5,6,11) - (1,2,3) = (4,4,8); rows U, V, N give (-4,4,8).
        I = r.camera_basis((0.0, 0.0, 2.0), (0.0, 3.0, 4.0), options())
        self.assertEqual(r.to_view(I, (5.0, 6.0, 11.0), (1.0, 2.0, 3.0)),
                         (-4.0, 4.0, 8.0))

    def test_projected_pixel(self):
        # (-4/8, 4/8) = (-0.5, 0.5): x = (int)(0.5 * 100/2) = 25 (25.0),
        # y = (int)((1 - 0.5) * 100/2) = 25.
        self.assertEqual(r.project((-4.0, 4.0, 8.0), TINY_CAMERA, 100, 100,
                                   options()), (25, 25))
        # (-0.3, 0.1) on 10x10: (int)(3.5) = 3 and (int)(4.5) = 4: truncated.
        self.assertEqual(r.project((-3.0, 1.0, 10.0), TINY_CAMERA, 10, 10,
                                   options()), (3, 4))
        # --round-vertices: 3.5 -> 4, 4.5 -> 5.
        self.assertEqual(r.project((-3.0, 1.0, 10.0), TINY_CAMERA, 10, 10,
                                   options("--round-vertices")), (4, 5))

    def test_width_for_height_scales_y_by_the_width(self):
        # (-0.3, 0.1) on 20x10: x = (int)(0.7 * 10) = 7; y = (int)(0.9 * 5) = 4,
        # with --width-for-height (int)(0.9 * 10) = 9.
        self.assertEqual(r.project((-3.0, 1.0, 10.0), TINY_CAMERA, 20, 10,
                                   options()), (7, 4))
        self.assertEqual(r.project((-3.0, 1.0, 10.0), TINY_CAMERA, 20, 10,
                                   options("--width-for-height")), (7, 9))

    def test_truncation_is_toward_zero_left_of_the_screen(self):
        # x/z = -1.1 on width 10: (int)(-0.1 * 5) = (int)(-0.5) = 0, a C cast.
        self.assertEqual(r.project((-11.0, 0.0, 10.0), TINY_CAMERA, 10, 10,
                                   options())[0], 0)

    def test_vertex_normals(self):
        I = r.camera_basis(TINY_CAMERA["N"], TINY_CAMERA["V"], options())
        view = [r.to_view(I, P, TINY_CAMERA["C"]) for P in TINY_POINTS]
        self.assertEqual(view, [(-4.0, -4.0, 8.0), (4.0, -4.0, 8.0),
                                (0.0, 4.0, 8.0)])
        # (B - A) x (C - A) = (8,0,0) x (4,8,0) = (0,0,64) -> (0,0,1).
        normals = r.vertex_normals(view, TINY_POINTS, [(0, 1, 2)], options())
        self.assertEqual(normals, [(0.0, 0.0, 1.0)] * 3)

    def test_one_lit_pixel(self):
        # Screen vertices (25,75), (75,75), (50,25).  Pixel (50,50) has
        # alfa = beta = 0.25, gama = 0.5, so P' = (0, 0, 8).  V = -P' ->
        # (0,0,-1); N = (0,0,1) gives V.N = -1 < 0, flipped to (0,0,-1).
        # L = (0,0,0) - P' -> (0,0,-1); N.L = 1; R = 2N - L = (0,0,-1);
        # R.V = 1.  I = Ia ka + Il Od kd + Il ks:
        #   r = 10 + 100 + 50 = 160, g = 20 + 25 + 25 = 70,
        #   b = 30 + 5 + 10 = 45.
        frame = r.render(TINY_CAMERA, TINY_LIGHT, TINY_POINTS, [(0, 1, 2)],
                         100, 100, options())
        self.assertEqual(pixel(frame, 50, 50), (160, 70, 45))
        self.assertEqual(frame.zbuffer[50 * 100 + 50], 8.0)

    def test_edges_are_inclusive_and_background_black(self):
        frame = r.render(TINY_CAMERA, TINY_LIGHT, TINY_POINTS, [(0, 1, 2)],
                         100, 100, options())
        for x, y in [(25, 75), (75, 75), (50, 25), (50, 75)]:
            self.assertNotEqual(pixel(frame, x, y), (0, 0, 0), (x, y))
        for x, y in [(24, 75), (76, 75), (50, 24), (50, 76), (0, 0)]:
            self.assertEqual(pixel(frame, x, y), (0, 0, 0), (x, y))

    def test_z_buffer_keeps_the_nearer(self):
        # A second, larger triangle behind (z = 16) and drawn after.
        behind = [(8.0, -8.0, 16.0), (-8.0, -8.0, 16.0), (0.0, 8.0, 16.0)]
        frame = r.render(TINY_CAMERA, TINY_LIGHT, TINY_POINTS + behind,
                         [(0, 1, 2), (3, 4, 5)], 100, 100, options())
        self.assertEqual(frame.zbuffer[50 * 100 + 50], 8.0)
        reversed_ = r.render(TINY_CAMERA, TINY_LIGHT, TINY_POINTS + behind,
                             [(0, 1, 2), (3, 4, 5)], 100, 100,
                             options("--depth-reversed"))
        self.assertEqual(reversed_.zbuffer[50 * 100 + 50], 16.0)

    def test_clamp_and_wrap(self):
        self.assertEqual(r.to_byte(300.7, options()), 255)
        self.assertEqual(r.to_byte(254.9, options()), 254)
        self.assertEqual(r.to_byte(300.7, options("--no-clamp")), 44)
        self.assertEqual(r.to_byte(100.0, options("--color-offset", "-120")),
                         0)
        self.assertEqual(r.to_byte(100.0, options("--color-scale", "1.5")),
                         150)


def pixel(frame, x, y):
    i = 3 * (y * frame.width + x)
    return tuple(frame.pixels[i:i + 3])


# ---------------------------------------------------------------------------
# A small scene where every switch shows: a camera away from the origin with
# N not unit and V not orthogonal to it, a smooth pyramid (shared vertices,
# faces of different areas), a faceted pyramid (duplicated positions), a
# large triangle behind both wound away from the viewer, ka != 1 and colours
# above 255.  The files are written with CRLF, blank lines and exponents.

CAMERA_FILE = "5 -3 -40\r\n0.1 0.05 2\r\n\r\n0.2 1 0.3\r\n1 0.3 0.3"
LIGHT_FILE = ("30 40 -30\r\n0.6\r\n200 30 20\r\n0.9\r\n0.9 0.6 0.3\r\n"
              "0.8\r\n255 220 200\r\n5")


def scene_object():
    smooth = [(-3, 0, -8), (-9, -5, 0), (2, -6, 0), (3, 4, 0), (-8, 5, 1)]
    tris = [(1, 2, 3), (1, 3, 4), (1, 4, 5), (1, 5, 2)]
    faceted_apex, base = (5, 0, -6), [(1, -6, 0), (10, -5, 0), (9, 6, 0),
                                      (2, 5, 0)]
    points = list(smooth)
    for k in range(4):
        n = len(points)
        points += [faceted_apex, base[k], base[(k + 1) % 4]]
        tris.append((n + 1, n + 2, n + 3))
    n = len(points)
    points += [(-12, -10, 5), (0, 12, 5), (12, -10, 5)]
    tris.append((n + 1, n + 2, n + 3))
    lines = [f"{len(points)} {len(tris)}", ""]
    lines += [f"{x:.4E} {y} {z}" for x, y, z in points] + [""]
    lines += [f"{a} {b} {c}" for a, b, c in tris]
    return "\r\n".join(lines) + "\r\n\r\n"


# Seed 000's special case at zero: a triangle in the plane z = 8 (view), the
# light 1e-5 in front of that plane and to the side, so that N.L is positive
# but below 1e-3 while R.V is large: the specular term shows unless N.L is
# tested against 1e-3.
EPS_CAMERA = "0 0 0\n0 0 1\n0 1 0\n1 1 1\n"
EPS_LIGHT = "-20 0 7.99999\n1\n10 10 10\n1\n1 1 1\n1\n255 255 255\n1\n"
EPS_OBJECT = "3 1\n4 -4 8\n-4 -4 8\n0 4 8\n1 2 3\n"

# The normals crossed the other way never reach the image: the turn toward the
# viewer undoes them (test_reversed_normals_are_invisible).
INVISIBLE = ["--triangle-normal-reversed"]
SWITCHES = [[s] for s, _ in r.MISTAKES if s not in INVISIBLE] + [
    ["--color-offset", "12"], ["--color-offset", "-12"],
    ["--color-scale", "0.5"], ["--flat-color", "255,0,0"]]


class Switches(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory()
        cls.scenes = {
            "main": write_scene(cls.dir.name, "main", CAMERA_FILE,
                                LIGHT_FILE, scene_object()),
            "eps": write_scene(cls.dir.name, "eps", EPS_CAMERA, EPS_LIGHT,
                               EPS_OBJECT)}
        cls.plain = {name: render_file(files, cls.dir.name, [])
                     for name, files in cls.scenes.items()}

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def render(self, scene, switches):
        return render_file(self.scenes[scene], self.dir.name, switches)

    def test_plain_image_covers_pixels(self):
        _, _, pixels = self.plain["main"]
        covered = sum(1 for i in range(0, len(pixels), 3)
                      if any(pixels[i:i + 3]))
        self.assertGreater(covered, 500)
        self.assertIn(255, pixels)          # some channel clamped

    def test_each_switch_changes_the_image(self):
        for switches in SWITCHES:
            scene = "eps" if switches == ["--epsilon-special-cases"] \
                else "main"
            with self.subTest(switches=switches):
                self.assertNotEqual(self.render(scene, switches)[2],
                                    self.plain[scene][2])

    def test_reversed_normals_are_invisible(self):
        self.assertEqual(self.render("main", INVISIBLE)[2],
                         self.plain["main"][2])

    def test_switches_combine(self):
        one = self.render("main", ["--flip-y"])[2]
        two = self.render("main", ["--flip-y", "--l-reversed"])[2]
        three = self.render("main", ["--flip-y", "--l-reversed",
                                     "--color-offset", "5"])[2]
        self.assertEqual(len({bytes(one), bytes(two), bytes(three)}), 3)

    def test_mirror_x_mirrors_the_plain_image(self):
        w, h, plain = self.plain["main"]
        _, _, mirrored = self.render("main", ["--mirror-x"])
        for y in range(h):
            for x in range(w):
                a, b = 3 * (y * w + x), 3 * (y * w + w - 1 - x)
                self.assertEqual(mirrored[a:a + 3], plain[b:b + 3])

    def test_pixels_transposed_swaps_x_and_y(self):
        w, h, plain = self.plain["main"]
        _, _, swapped = self.render("main", ["--pixels-transposed"])
        for y in range(h):
            for x in range(w):
                a = 3 * (y * w + x)
                b = 3 * (x * w + y) if x < h else None
                expected = plain[b:b + 3] if b is not None else bytes(3)
                self.assertEqual(swapped[a:a + 3], expected)

    def test_v_equals_p_gives_the_l_reversed_image(self):
        self.assertEqual(self.render("main", ["--v-equals-p"])[2],
                         self.render("main", ["--l-reversed"])[2])

    def test_data_after_the_counts_is_ignored(self):
        camera, light, obj = self.scenes["eps"]
        longer = obj + "_long.byu"
        with open(obj) as f, open(longer, "w") as g:
            g.write(f.read() + "\n1 2 3\n")
        self.assertEqual(r.read_object(longer), r.read_object(obj))


def write_scene(folder, name, camera, light, obj):
    paths = []
    for suffix, text in [("cfg", camera), ("txt", light), ("byu", obj)]:
        path = os.path.join(folder, f"{name}.{suffix}")
        with open(path, "w", newline="") as f:
            f.write(text)
        paths.append(path)
    return paths


def render_file(files, folder, switches):
    """Runs the command line and reads its PNG back."""
    out = os.path.join(folder, "out.png")
    camera, light, obj = files
    r.main(["--camera", camera, "--lighting", light, "--object", obj,
            "--size", "80x60", "--output", out, *switches])
    return pngdiff.read_png(out)


if __name__ == "__main__":
    unittest.main()
