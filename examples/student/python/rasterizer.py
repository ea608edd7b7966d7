#!/usr/bin/env python3
"""A student's software rasterizer for seed 000 (UFPE/UFRPE course project).

Written from the seed's text and the course's file formats only, in plain
Python 3.11 with the standard library.  It reads the course's camera,
lighting and .byu object files, follows the seed's steps one by one and
writes an 8-bit RGB PNG.  Each --switch below puts one classic student
mistake into the pipeline, so that tests can feed RasterLab's `compare`
with images whose mistake is known.

    python3 rasterizer.py --camera calice2.cfg --lighting iluminacao.txt \\
        --object calice2.byu --size 800x600 --output out.png [mistakes]

Readings of the seed where its text leaves a choice (each repeated where it
is made):
  * Screen vertices are truncated with (int), as the seed writes; the pixel
    P = (x, y) is sampled at its integer coordinates (the pixel's corner, not
    its centre), in the same integer space as the truncated vertices.
  * "Pixel interno do triangulo": a pixel is inside when its three
    barycentric coordinates are >= 0 (edges inclusive).  Edges shared by two
    triangles are drawn by both and the z-buffer (strict <) keeps the first.
  * Colour bytes: each channel is clamped to 255 as the seed says, then
    truncated to an integer, as a C cast (int) would.
  * Phong as the course writes it: I = Ia*ka + Il*Od*kd*(N.L) + Il*ks*(R.V)^n.
  * A triangle with a vertex at view z == 0 is skipped (the seed's division
    by z is undefined there); vertices behind the camera are divided by their
    negative z, as the seed writes (no clipping).  A triangle whose three
    screen vertices are collinear has no solution to the barycentric system
    and is skipped.  A degenerate triangle (zero-length normal) adds nothing
    to its vertices' normals.
"""

import argparse
import math
import struct
import sys
import zlib

# ---------------------------------------------------------------------------
# Small vector helpers (3-tuples of floats)


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def normalize(a):
    """a / |a|; a zero vector stays zero (nothing to normalise)."""
    length = math.sqrt(dot(a, a))
    if length == 0.0:
        return a
    return (a[0] / length, a[1] / length, a[2] / length)


# ---------------------------------------------------------------------------
# Input files


def read_numbers(path):
    """All whitespace-separated tokens of a file.

    Splitting on any whitespace takes CRLF or LF endings, blank lines, TABs
    and a missing last newline in stride; float() reads exponents such as
    E-15 or 9.5e-005 whatever the locale.
    """
    with open(path, "r", encoding="latin-1") as f:
        return f.read().split()


def take_floats(tokens, count, path, what):
    if len(tokens) < count:
        sys.exit(f"{path}: expected {count} numbers for {what}, "
                 f"found {len(tokens)}")
    try:
        return [float(t) for t in tokens[:count]]
    except ValueError as error:
        sys.exit(f"{path}: {what}: {error}")


def read_camera(path):
    """UFPE camera: C, N, V, then d hx hy on one line."""
    v = take_floats(read_numbers(path), 12, path, "C, N, V, d hx hy")
    return {"C": tuple(v[0:3]), "N": tuple(v[3:6]), "V": tuple(v[6:9]),
            "d": v[9], "hx": v[10], "hy": v[11]}


def read_lighting(path):
    """UFPE lighting: Pl, ka, Ia, kd, Od, ks, Il, n (16 numbers)."""
    v = take_floats(read_numbers(path), 16, path,
                    "Pl, ka, Ia, kd, Od, ks, Il, n")
    return {"Pl": tuple(v[0:3]), "ka": v[3], "Ia": tuple(v[4:7]),
            "kd": v[7], "Od": tuple(v[8:11]), "ks": v[11],
            "Il": tuple(v[12:15]), "n": v[15]}


def read_object(path):
    """.byu: "nVerts nTris", the vertices x y z, the 1-based triangles."""
    tokens = read_numbers(path)
    if len(tokens) < 2:
        sys.exit(f"{path}: expected the counts of vertices and triangles")
    try:
        n_points, n_triangles = int(tokens[0]), int(tokens[1])
    except ValueError:
        sys.exit(f"{path}: the header must be two integers")
    body = tokens[2:]
    coords = take_floats(body, 3 * n_points, path, "the vertices")
    points = [tuple(coords[3 * i:3 * i + 3]) for i in range(n_points)]
    rest = body[3 * n_points:]
    indices = take_floats(rest, 3 * n_triangles, path, "the triangles")
    triangles = []
    for t in range(n_triangles):
        tri = tuple(int(indices[3 * t + k]) - 1 for k in range(3))
        if min(tri) < 0 or max(tri) >= n_points:
            sys.exit(f"{path}: triangle {t + 1} names a vertex out of "
                     f"1..{n_points}")
        triangles.append(tri)
    if len(rest) > 3 * n_triangles:
        print(f"warning: {path}: data after the declared {n_triangles} "
              "triangles is ignored", file=sys.stderr)
    return points, triangles


# ---------------------------------------------------------------------------
# Camera: Gram-Schmidt basis and view coordinates


def camera_basis(N, V, opts):
    """The seed's alfa = {U, V, N}: the rows of [I]e,alfa.

    proj_N(V) is written (V.N)N, the formula for a unit N, so the step
    "Normalizar N" matters (--no-normalize-n-before-gram-schmidt skips it).
    """
    if not opts.no_normalize_n_before_gram_schmidt:
        N = normalize(N)
    V = sub(V, scale(N, dot(V, N)))
    V = normalize(V)
    U = cross(V, N) if opts.u_v_cross_n else cross(N, V)
    return U, V, N


def to_view(I, P, C):
    """[I]e,alfa * (P - C)."""
    D = sub(P, C)
    return (dot(I[0], D), dot(I[1], D), dot(I[2], D))


def light_in_view(I, Pl, C, opts):
    if opts.light_in_world:
        return Pl
    if opts.light_no_minus_c:
        return (dot(I[0], Pl), dot(I[1], Pl), dot(I[2], Pl))
    x, y, z = to_view(I, Pl, C)
    return (y, x, z) if opts.light_swap_xy else (x, y, z)


# ---------------------------------------------------------------------------
# Normals


def triangle_normal(A, B, C, opts):
    if opts.triangle_normal_reversed:
        n = cross(sub(C, A), sub(B, A))
    else:
        n = cross(sub(B, A), sub(C, A))
    return n if opts.sum_unnormalized_triangle_normals else normalize(n)


def vertex_normals(points_view, points_world, triangles, opts):
    """Sum of the (normalised) triangle normals at each vertex, normalised.

    --normals-shared-by-position sums over every vertex at the same world
    position (a faceted mesh's duplicated vertices then share one normal).
    """
    key = list(range(len(points_view)))
    if opts.normals_shared_by_position:
        first = {}
        key = [first.setdefault(p, i) for i, p in enumerate(points_world)]
    sums = [(0.0, 0.0, 0.0)] * len(points_view)
    for a, b, c in triangles:
        n = triangle_normal(points_view[a], points_view[b], points_view[c],
                            opts)
        for i in (a, b, c):
            sums[key[i]] = add(sums[key[i]], n)
    normals = [sums[key[i]] for i in range(len(points_view))]
    if opts.vertex_normals_unnormalized:
        return normals
    return [normalize(n) for n in normals]


# ---------------------------------------------------------------------------
# Projection to the screen


def to_int(value, opts):
    """The seed's (int) cast truncates toward zero; --round-vertices rounds."""
    if opts.round_vertices:
        return math.floor(value + 0.5)
    return int(value)


def project(P, camera, width, height, opts):
    """Screen pixel (x, y) of a view-space point, or None when z == 0.

    The seed's formulas: ((d/hx) x/z, (d/hy) y/z) in [-1, 1], then
    x = (int)((x + 1) * width / 2), y = (int)((1 - y) * height / 2).
    --flip-y writes (y + 1) for (1 - y); --width-for-height scales y by
    width / 2 as x is (the image stretched down when it is wider than
    tall).  A mirror of x in this formula
    would give exactly --u-v-cross-n's image, so --mirror-x mirrors the
    finished image instead (mirror_columns).  The two give one image while
    every a = (x + 1) * width / 2 lies in (0, width) and is not whole:
    (int)(width - a) is then width - 1 - (int)a, and the integer sample
    points mirror onto integer sample points.  Vertices left of the screen
    (a < 0, truncated toward zero) or at whole a make them differ.
    """
    if P[2] == 0.0:
        return None
    sx = (camera["d"] / camera["hx"]) * (P[0] / P[2])
    sy = (camera["d"] / camera["hy"]) * (P[1] / P[2])
    fx = sx + 1
    fy = (sy + 1) if opts.flip_y else (1 - sy)
    rows = width if opts.width_for_height else height
    return (to_int(fx * width / 2, opts), to_int(fy * rows / 2, opts))


# ---------------------------------------------------------------------------
# Phong


def phong_terms(P, N, light, Pl, opts):
    """The three Phong terms (ambient, diffuse, specular), per channel.

    Follows the seed: V = -P', L = Pl - P'; normalise N, V, L; flip N when
    V.N < 0; no diffuse nor specular when N.L < 0; R = 2(N.L)N - L,
    normalised; no specular when R.V < 0.

    --v-equals-p and --l-reversed give the same image: with -V the flip
    turns N to -N, so N.L and R.V change sign exactly as with -L.
    """
    eps = 1e-3 if opts.epsilon_special_cases else 0.0
    V = P if opts.v_equals_p else (-P[0], -P[1], -P[2])
    L = sub(P, Pl) if opts.l_reversed else sub(Pl, P)
    N, V, L = normalize(N), normalize(V), normalize(L)
    if not opts.no_flip_normal and dot(V, N) < eps:
        N = (-N[0], -N[1], -N[2])
    ambient = ambient_term(light, opts)
    NL = dot(N, L)
    if NL < eps:
        return ambient, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)
    Il, Od = light["Il"], light["Od"]
    kd = light["kd"]
    diffuse = (Il[0] * Od[0] * kd * NL, Il[1] * Od[1] * kd * NL,
               Il[2] * Od[2] * kd * NL)
    R = normalize(sub(scale(N, 2 * NL), L))
    RV = dot(R, V)
    if RV < eps:
        return ambient, diffuse, (0.0, 0.0, 0.0)
    s = light["ks"] * RV ** light["n"]
    return ambient, diffuse, (Il[0] * s, Il[1] * s, Il[2] * s)


def ambient_term(light, opts):
    """Ia*ka; --ambient-ia-only drops ka (visible only when ka != 1);
    --ambient-times-od multiplies by Od as the diffuse term does."""
    Ia, ka, Od = light["Ia"], light["ka"], light["Od"]
    if opts.ambient_ia_only:
        return Ia
    if opts.ambient_times_od:
        return (Ia[0] * ka * Od[0], Ia[1] * ka * Od[1], Ia[2] * ka * Od[2])
    return (Ia[0] * ka, Ia[1] * ka, Ia[2] * ka)


def phong(P, N, light, Pl, opts):
    """The pixel's intensity per channel, before clamping."""
    a, d, s = phong_terms(P, N, light, Pl, opts)
    if opts.truncate_terms:
        return tuple(int(a[k]) + int(d[k]) + int(s[k]) for k in range(3))
    return (a[0] + d[0] + s[0], a[1] + d[1] + s[1], a[2] + d[2] + s[2])


def to_byte(value, opts):
    """Clamp to 255 as the seed says, then truncate (a C cast).

    --color-scale multiplies the intensity before; --no-clamp wraps modulo
    256 instead; --color-offset adds to the byte after, clamped to 0..255.
    """
    value *= opts.color_scale
    if opts.no_clamp:
        byte = int(value) % 256
    else:
        byte = int(min(max(value, 0.0), 255.0))
    if opts.color_offset:
        byte = min(max(byte + opts.color_offset, 0), 255)
    return byte


# ---------------------------------------------------------------------------
# Scanline conversion


def span(edges, y):
    """The x range [x0, x1] of row y where every edge function A*x + B >= 0.

    Exact in integers: the screen vertices are whole pixels, so each edge
    function (den times a barycentric coordinate) is an integer.
    """
    x0, x1 = -math.inf, math.inf
    for A, B0, By in edges:
        B = B0 + By * y
        if A > 0:
            x0 = max(x0, -(B // A))        # x >= ceil(-B / A)
        elif A < 0:
            x1 = min(x1, B // -A)          # x <= floor(B / -A)
        elif B < 0:
            return None
    return (x0, x1) if x0 <= x1 else None


def edge_functions(p1, p2, p3):
    """den and the edge functions of alfa, beta, gama as (A, B0, By):
    den*alfa(x, y) = A*x + B0 + By*y.  None when the triangle is a line."""
    (x1, y1), (x2, y2), (x3, y3) = p1, p2, p3
    den = (y2 - y3) * (x1 - x3) + (x3 - x2) * (y1 - y3)
    if den == 0:
        return None
    s = 1 if den > 0 else -1
    a = ((y2 - y3) * s, (-(y2 - y3) * x3 - (x3 - x2) * y3) * s, (x3 - x2) * s)
    b = ((y3 - y1) * s, (-(y3 - y1) * x3 - (x1 - x3) * y3) * s, (x1 - x3) * s)
    g = (-a[0] - b[0], den * s - a[1] - b[1], -a[2] - b[2])
    return den * s, (a, b, g)


class Frame:
    """Colour image, z-buffer and the scene's shading inputs."""

    def __init__(self, width, height, opts):
        self.width, self.height, self.opts = width, height, opts
        self.pixels = bytearray(3 * width * height)       # black background
        far = -math.inf if opts.depth_reversed else math.inf
        self.zbuffer = [far] * (width * height)

    def closer(self, z, index):
        """The seed's test P'.z < z-buffer; --depth-reversed: farther wins."""
        if self.opts.depth_reversed:
            return z > self.zbuffer[index]
        if self.opts.zbuffer_ties_later:
            return z <= self.zbuffer[index]
        return z < self.zbuffer[index]

    def paint(self, index, color):
        o = self.opts
        self.pixels[3 * index:3 * index + 3] = bytes(
            to_byte(c, o) for c in color)


def triangle_spans(screen, width, height, opts):
    """The pixels of a triangle on the screen, as (y, x_first, x_last) rows.

    Pixel P = (x, y) is sampled at its integer coordinates, the same space
    as the truncated vertices; alfa, beta, gama >= 0 (edges inclusive).
    --span-end-exclusive stops each row one pixel early (range(x0, x1)).
    Yields nothing for a triangle whose vertices are collinear.
    """
    found = edge_functions(*screen)
    if found is None:
        return
    den, edges = found
    ys = [p[1] for p in screen]
    y_first, y_last = max(min(ys), 0), min(max(ys), height - 1)
    for y in range(y_first, y_last + 1):
        xs = span(edges, y)
        if xs is None:
            continue
        x0, x1 = max(xs[0], 0), min(xs[1], width - 1)
        if opts.span_end_exclusive:
            x1 -= 1
        if x0 <= x1:
            yield y, x0, x1


def draw_triangle(frame, screen, view, normals, colors, light, Pl):
    """Scanline conversion of one triangle with per-pixel barycentrics."""
    found = edge_functions(*screen)
    if found is None:
        return
    den, edges = found
    for y, x0, x1 in triangle_spans(screen, frame.width, frame.height,
                                    frame.opts):
        for x in range(x0, x1 + 1):
            bary = [(A * x + B0 + By * y) / den for A, B0, By in edges]
            shade_pixel(frame, x, y, bary, view, normals, colors, light, Pl)


def interpolate(bary, a, b, c):
    alfa, beta, gama = bary
    return (alfa * a[0] + beta * b[0] + gama * c[0],
            alfa * a[1] + beta * b[1] + gama * c[1],
            alfa * a[2] + beta * b[2] + gama * c[2])


def shade_pixel(frame, x, y, bary, view, normals, colors, light, Pl):
    """z-buffer test on P' and Phong (or Gouraud / flat colour) at P."""
    alfa, beta, gama = bary
    z = alfa * view[0][2] + beta * view[1][2] + gama * view[2][2]
    index = y * frame.width + x
    if not frame.closer(z, index):
        return
    frame.zbuffer[index] = z
    opts = frame.opts
    if opts.flat_color is not None:
        color = opts.flat_color
    elif colors is not None:                              # Gouraud
        color = interpolate(bary, *colors)
    else:
        P = interpolate(bary, *view)
        N = interpolate(bary, *normals)
        color = phong(P, N, light, Pl, opts)
    frame.paint(index, color)


# ---------------------------------------------------------------------------
# The pipeline


def render(camera, light, points, triangles, width, height, opts):
    """The seed's steps in order; returns the Frame."""
    I = camera_basis(camera["N"], camera["V"], opts)
    C = camera["C"]
    Pl = light_in_view(I, light["Pl"], C, opts)
    view = [to_view(I, P, C) for P in points]
    normals = vertex_normals(view, points, triangles, opts)
    screen = [project(P, camera, width, height, opts) for P in view]
    vertex_colors = None
    if opts.gouraud and opts.flat_color is None:
        vertex_colors = [phong(P, N, light, Pl, opts)
                         for P, N in zip(view, normals)]
    frame = Frame(width, height, opts)
    for tri in triangles:
        s = [screen[i] for i in tri]
        if None in s:
            continue                      # a vertex at z == 0: skipped
        colors = None if vertex_colors is None else \
            [vertex_colors[i] for i in tri]
        draw_triangle(frame, s, [view[i] for i in tri],
                      [normals[i] for i in tri], colors, light, Pl)
    if opts.mirror_x:
        mirror_columns(frame)
    if opts.pixels_transposed:
        transpose_pixels(frame)
    return frame


def transpose_pixels(frame):
    """--pixels-transposed: pixel (x, y) written at column y of row x, as
    when a 2D array indexed [x][y] is written out row by row; what falls
    outside a wider-than-tall image is lost, the rest stays black."""
    w, h = frame.width, frame.height
    old = bytes(frame.pixels)
    frame.pixels[:] = bytes(3 * w * h)
    for y in range(min(h, w)):
        for x in range(min(w, h)):
            i, j = 3 * (y * w + x), 3 * (x * w + y)
            frame.pixels[j:j + 3] = old[i:i + 3]


def mirror_columns(frame):
    """--mirror-x: the image written with its columns in reverse order
    (x -> width - 1 - x), as when a row is stored from its end."""
    w = frame.width
    for y in range(frame.height):
        row = frame.zbuffer[y * w:(y + 1) * w]
        frame.zbuffer[y * w:(y + 1) * w] = row[::-1]
        for x in range(w // 2):
            a, b = 3 * (y * w + x), 3 * (y * w + w - 1 - x)
            frame.pixels[a:a + 3], frame.pixels[b:b + 3] = \
                frame.pixels[b:b + 3], frame.pixels[a:a + 3]


# ---------------------------------------------------------------------------
# PNG output


def png_chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + \
        struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def write_png(path, width, height, rgb):
    """8-bit RGB, no interlace, filter 0 on every row."""
    stride = 3 * width
    raw = bytearray()
    for y in range(height):
        raw.append(0)
        raw += rgb[y * stride:(y + 1) * stride]
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(png_chunk(b"IHDR", header))
        f.write(png_chunk(b"IDAT", zlib.compress(bytes(raw), 6)))
        f.write(png_chunk(b"IEND", b""))


# ---------------------------------------------------------------------------
# Command line

MISTAKES = [
    ("--light-in-world", "the light's Pl used as it is, not taken to view"
     " coordinates"),
    ("--light-no-minus-c", "Pl_vista = [I]*Pl, without subtracting C"),
    ("--light-swap-xy", "Pl_vista's x and y swapped (read in the wrong order)"),
    ("--v-equals-p", "V = P' instead of -P'"),
    ("--l-reversed", "L = P' - Pl instead of Pl - P'"),
    ("--no-normalize-n-before-gram-schmidt", "N not normalised before"
     " V - (V.N)N (nor after)"),
    ("--u-v-cross-n", "U = V x N instead of N x V"),
    ("--vertex-normals-unnormalized", "the vertex normals' sums not"
     " normalised"),
    ("--sum-unnormalized-triangle-normals", "triangle normals summed at their"
     " length (area-weighted)"),
    ("--normals-shared-by-position", "vertices at the same position share"
     " one normal"),
    ("--truncate-terms", "each Phong term truncated to a whole number before"
     " the sum"),
    ("--epsilon-special-cases", "V.N, N.L, R.V tested against 1e-3 instead"
     " of 0"),
    ("--depth-reversed", "z-buffer from -infinity, the farther fragment"
     " wins"),
    ("--round-vertices", "screen vertices rounded instead of truncated"),
    ("--mirror-x", "the finished image mirrored left-right (columns"
     " written in reverse)"),
    ("--flip-y", "screen y = (int)((y + 1) * height / 2): y grows upward"),
    ("--width-for-height", "screen y = (int)((1 - y) * width / 2): the"
     " width where the height belongs"),
    ("--pixels-transposed", "pixel (x, y) written at (y, x): x and y"
     " swapped in the pixel's index"),
    ("--no-flip-normal", "N not turned toward the viewer where V.N < 0"),
    ("--ambient-ia-only", "ambient term Ia instead of Ia*ka (changes the"
     " image only when ka != 1)"),
    ("--ambient-times-od", "ambient term Ia*ka*Od instead of Ia*ka"),
    ("--gouraud", "Phong lighting at the vertices, colours interpolated"),
    ("--no-clamp", "channels above 255 wrap modulo 256 instead of"
     " clamping"),
    ("--triangle-normal-reversed", "triangle normal (P3 - P1) x (P2 - P1):"
     " the cross product in the other order"),
    ("--span-end-exclusive", "each span stops one pixel early (x < x_last)"),
    ("--zbuffer-ties-later", "z-buffer test z <= stored: on a tie the later"
     " fragment wins"),
]


def parse_size(text):
    try:
        w, h = text.lower().split("x")
        w, h = int(w), int(h)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WxH, found '{text}'")
    if w < 1 or h < 1:
        raise argparse.ArgumentTypeError("the size must be positive")
    return w, h


def parse_rgb(text):
    try:
        r, g, b = (int(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected R,G,B, found '{text}'")
    return (float(r), float(g), float(b))


def make_parser():
    p = argparse.ArgumentParser(
        description="Seed 000's rasterizer, as a student would write it, "
        "with switches that put in one classic mistake each.")
    p.add_argument("--camera", required=True, help="UFPE camera file")
    p.add_argument("--lighting", required=True, help="UFPE lighting file")
    p.add_argument("--object", required=True, help=".byu object")
    p.add_argument("--size", type=parse_size, default=(800, 600),
                   help="image size WxH (default 800x600)")
    p.add_argument("--output", required=True, help="PNG to write")
    p.add_argument("--timing", action="store_true",
                   help="print the time the render took to stderr")
    add_mistakes(p)
    return p


def add_mistakes(p):
    """The mistake switches, shared with stages.py."""
    m = p.add_argument_group("mistakes (combinable)")
    for flag, text in MISTAKES:
        m.add_argument(flag, action="store_true", help=text)
    m.add_argument("--color-offset", type=int, default=0, metavar="K",
                   help="every covered pixel's bytes K higher (K < 0: lower),"
                   " clamped")
    m.add_argument("--color-scale", type=float, default=1.0, metavar="S",
                   help="every intensity multiplied by S before clamping")
    m.add_argument("--flat-color", type=parse_rgb, default=None,
                   metavar="R,G,B", help="unlit: every covered pixel R,G,B")


def main(argv=None):
    import time
    opts = make_parser().parse_args(argv)
    camera = read_camera(opts.camera)
    light = read_lighting(opts.lighting)
    points, triangles = read_object(opts.object)
    width, height = opts.size
    start = time.perf_counter()
    frame = render(camera, light, points, triangles, width, height, opts)
    elapsed = time.perf_counter() - start
    write_png(opts.output, width, height, frame.pixels)
    if opts.timing:
        print(f"rendered {len(triangles)} triangles at {width}x{height} in "
              f"{elapsed:.2f} s", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
