#!/usr/bin/env python3
"""HW2: 3D Rasterizer, as a student writes it (Python 3.11, standard library).

    python3 rasterizer.py FILE.txt [--ignore-multmv] [--depth-reversed]

Reads the command file and writes every PNG its `png` commands name, in the
current folder.  Unsupported commands are reported as FILE:LINE and skipped.

Readings made where the homework text leaves a choice:
  * vertex indices are 1-based; a negative index counts from the end (-1 is
    the last vertex defined so far), as in HW1;
  * matrices: model/view commands multiply on the right (M = M * T), so the
    last command given is applied to the point first; a point p becomes
    P * MV * p, then x, y, z are divided by w;
  * viewport: x = (x + 1) * (width / 2), y likewise with height, y = -1
    at the top row of the image (png rows go down);
  * scan conversion in double: DDA along y then along x, pixels at integer
    coordinates, rows ceil(y_top) <= y < y_bottom, columns ceil(x_left) <= x
    < x_right, every attribute stepped by adding a per-pixel increment;
    the first step goes straight to the first row (column) on the screen and
    the loop stops at the screen's edge (the "efficient screen clipping");
  * a fragment is kept when 0 <= x < width, 0 <= y < height, 0 <= z <= 1 and
    z <= depth buffer (initially 1) -- the depth buffer is always on, as the
    required part says; colours are clamped to [0, 1] and mapped to bytes
    with int(255 * c); drawn pixels get alpha 255, the rest stay (0,0,0,0);
  * frustum and ortho use OpenGL's matrices (ortho with near = 2n - f);
  * colours are interpolated perspective-correct (Q/w and 1/w, then divided);
  * clip planes are used as given (not moved by the model/view), applied to
    the model/viewed vertices; `cull` keeps triangles counter-clockwise as
    seen in the image; rectbez quads are split along the (i+1,j)-(i,j+1)
    diagonal.

--ignore-multmv makes `multmv` do nothing (a classic mistake, for tests).
"""

import math
import struct
import sys
import zlib


# ---------------------------------------------------------------- matrices

def identity():
    return [[1.0 if r == c else 0.0 for c in range(4)] for r in range(4)]


def mult4by4(a, b):
    return [[sum(a[r][i] * b[i][c] for i in range(4)) for c in range(4)]
            for r in range(4)]


def mult_m_v(m, v):
    return [sum(m[r][i] * v[i] for i in range(4)) for r in range(4)]


def from_row_major(nums):
    return [[nums[4 * r + c] for c in range(4)] for r in range(4)]


def translate(dx, dy, dz):
    m = identity()
    m[0][3], m[1][3], m[2][3] = dx, dy, dz
    return m


def scale(sx, sy, sz):
    m = identity()
    m[0][0], m[1][1], m[2][2] = sx, sy, sz
    return m


def rotate(degrees, x, y, z):
    """Counter-clockwise rotation about the axis (x, y, z), as glRotate."""
    length = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / length, y / length, z / length
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)
    t = 1 - c
    return [[x * x * t + c, x * y * t - z * s, x * z * t + y * s, 0.0],
            [y * x * t + z * s, y * y * t + c, y * z * t - x * s, 0.0],
            [z * x * t - y * s, z * y * t + x * s, z * z * t + c, 0.0],
            [0.0, 0.0, 0.0, 1.0]]


def frustum(l, r, b, t, n, f):
    return [[2 * n / (r - l), 0.0, (r + l) / (r - l), 0.0],
            [0.0, 2 * n / (t - b), (t + b) / (t - b), 0.0],
            [0.0, 0.0, -(f + n) / (f - n), -2 * f * n / (f - n)],
            [0.0, 0.0, -1.0, 0.0]]


def ortho(l, r, b, t, n, f):
    n = 2 * n - f   # the homework's box is [-f, -n] in z, mapped to [0, 1]
    return [[2 / (r - l), 0.0, 0.0, -(r + l) / (r - l)],
            [0.0, 2 / (t - b), 0.0, -(t + b) / (t - b)],
            [0.0, 0.0, -2 / (f - n), -(f + n) / (f - n)],
            [0.0, 0.0, 0.0, 1.0]]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0]]


def normalize(v):
    length = math.sqrt(sum(c * c for c in v))
    return [c / length for c in v]


def lookat(eye, center, up):
    """gluLookAt's matrix."""
    f = normalize(sub(center, eye))
    s = normalize(cross(f, normalize(up)))
    u = cross(s, f)
    m = [s + [0.0], u + [0.0], [-c for c in f] + [0.0], [0.0, 0.0, 0.0, 1.0]]
    return mult4by4(m, translate(-eye[0], -eye[1], -eye[2]))


# ---------------------------------------------------------------- PNG

def write_png(filename, width, height, rgba):
    raw = b''.join(b'\x00' + bytes(rgba[y * width * 4:(y + 1) * width * 4])
                   for y in range(height))

    def chunk(kind, data):
        body = kind + data
        return (struct.pack('>I', len(data)) + body
                + struct.pack('>I', zlib.crc32(body) & 0xffffffff))

    with open(filename, 'wb') as out:
        out.write(b'\x89PNG\r\n\x1a\n')
        out.write(chunk(b'IHDR', struct.pack('>IIBBBBB', width, height,
                                             8, 6, 0, 0, 0)))
        out.write(chunk(b'IDAT', zlib.compress(raw, 9)))
        out.write(chunk(b'IEND', b''))


class Image:
    def __init__(self, width, height, filename, depth_reversed=False):
        self.width, self.height, self.filename = width, height, filename
        self.rgba = bytearray(width * height * 4)
        # --depth-reversed: the classic slip, a buffer cleared to 0 and the
        # farther fragment kept.
        self.depth_reversed = depth_reversed
        self.depth = [0.0 if depth_reversed else 1.0] * (width * height)

    def fragment(self, x, y, z, color):
        """Per-pixel clipping, depth test, then set the pixel."""
        if not (0 <= x < self.width and 0 <= y < self.height):
            return
        if not (0.0 <= z <= 1.0):
            return
        i = y * self.width + x
        if (z < self.depth[i]) if self.depth_reversed else (z > self.depth[i]):
            return
        self.depth[i] = z
        self.rgba[4 * i:4 * i + 4] = bytes(to_byte(c) for c in color) + b'\xff'


def to_byte(c):
    if c <= 0.0:
        return 0
    if c >= 1.0:
        return 255
    return int(c * 255)


# ---------------------------------------------------------------- DDA

def dda(a, b, d, low, high):
    """Points of the segment a-b at each integer value of coordinate d,
    from ceil(a[d]) while < b[d], kept to low <= d < high; every coordinate
    stepped by adding."""
    if a[d] == b[d]:
        return
    if a[d] > b[d]:
        a, b = b, a
    delta = [(bi - ai) / (b[d] - a[d]) for ai, bi in zip(a, b)]
    start = max(math.ceil(a[d]), low)
    offset = start - a[d]
    p = [ai + offset * di for ai, di in zip(a, delta)]
    i = start
    while i < b[d] and i < high:
        p[d] = i          # the stepped coordinate is the integer itself
        yield p
        p = [pi + di for pi, di in zip(p, delta)]
        i += 1


def scanline(image, p, q, r):
    """Fill the triangle whose vertices are [x, y, z, 1/w, r/w, g/w, b/w]
    (x, y in pixels)."""
    top, mid, bot = sorted((p, q, r), key=lambda v: v[1])
    h, w = image.height, image.width
    long_edge = dda(top, bot, 1, 0, h)
    for short in (dda(top, mid, 1, 0, h), dda(mid, bot, 1, 0, h)):
        for a in short:
            b = next(long_edge)
            for f in dda(a, b, 0, 0, w):
                color = [c / f[3] for c in f[4:]]
                image.fragment(int(f[0]), int(f[1]), f[2], color)


# ---------------------------------------------------------------- commands

def lerp(a, b, t):
    return [ai + t * (bi - ai) for ai, bi in zip(a, b)]


def clip(polygon, plane):
    """Keep the part of a polygon (lists [x, y, z, w, ...]) where
    plane . (x, y, z, w) >= 0; attributes are interpolated too."""
    out = []
    for i, p in enumerate(polygon):
        q = polygon[(i + 1) % len(polygon)]
        dp = sum(plane[k] * p[k] for k in range(4))
        dq = sum(plane[k] * q[k] for k in range(4))
        if dp >= 0:
            out.append(p)
        if (dp >= 0) != (dq >= 0):
            out.append(lerp(p, q, dp / (dp - dq)))
    return out


def bezier_patch(grid, s, t):
    """de Casteljau on a 4x4 grid of vectors: each step interpolates every
    quad at (s, t), giving a grid one smaller, down to a single point."""
    while len(grid) > 1:
        grid = [[lerp(lerp(grid[r][c], grid[r][c + 1], s),
                      lerp(grid[r + 1][c], grid[r + 1][c + 1], s), t)
                 for c in range(len(grid) - 1)] for r in range(len(grid) - 1)]
    return grid[0][0]


class Rasterizer:
    def __init__(self, ignore_multmv=False, depth_reversed=False):
        self.ignore_multmv = ignore_multmv
        self.depth_reversed = depth_reversed
        self.images = []
        self.image = None
        self.vertices = []        # [x, y, z, w, r, g, b]
        self.color = [1.0, 1.0, 1.0]
        self.mv = identity()
        self.proj = identity()
        self.planes = []
        self.cull = False

    def vertex(self, index):
        i = int(index)
        return self.vertices[i - 1 if i > 0 else i]

    def point3(self, index):
        x, y, z, w = self.vertex(index)[:4]
        return [x / w, y / w, z / w]

    def add_mv(self, m):
        self.mv = mult4by4(self.mv, m)

    def to_screen(self, v):
        """Projection, divide by w, viewport (v is already model/viewed)."""
        x, y, z, w = mult_m_v(self.proj, v[:4])
        if w == 0:
            return None
        x, y, z = x / w, y / w, z / w
        x = (x + 1) * (self.image.width / 2)
        y = (y + 1) * (self.image.height / 2)
        # perspective-correct interpolation: carry 1/w and Q/w
        return [x, y, z, 1 / w] + [q / w for q in v[4:]]

    def triangle(self, verts, gouraud):
        """verts: three [x, y, z, w, r, g, b] in model coordinates."""
        if self.image is None:
            return
        polygon = []
        for v in verts:
            color = v[4:7] if gouraud else self.color
            polygon.append(mult_m_v(self.mv, v[:4]) + list(color))
        for plane in self.planes:
            polygon = clip(polygon, plane)
        points = [self.to_screen(v) for v in polygon]
        if len(points) < 3 or None in points:
            return
        for i in range(1, len(points) - 1):    # a fan of triangles
            a, b, c = points[0], points[i], points[i + 1]
            if self.cull:
                area = ((b[0] - a[0]) * (c[1] - a[1])
                        - (b[1] - a[1]) * (c[0] - a[0]))
                if area >= 0:    # y goes down: counter-clockwise is < 0
                    continue
            scanline(self.image, a, b, c)

    def rectbez(self, args, gouraud):
        n = 2 ** int(args[0])
        ctrl = [self.vertex(i) for i in args[1:17]]
        grid = [ctrl[4 * r:4 * r + 4] for r in range(4)]
        pts = [[bezier_patch(grid, i / n, j / n) for i in range(n + 1)]
               for j in range(n + 1)]
        for j in range(n):
            for i in range(n):
                a, b = pts[j][i], pts[j][i + 1]
                c, d = pts[j + 1][i + 1], pts[j + 1][i]
                self.triangle([a, b, d], gouraud)
                self.triangle([b, c, d], gouraud)

    ARGS = {'png': 3, 'xyz': 3, 'xyzw': 4, 'color': 3, 'trif': 3, 'trig': 3,
            'rectbezf': 17, 'rectbezg': 17, 'clipplane': 4, 'cull': 0,
            'loadmv': 16, 'loadp': 16, 'multmv': 16, 'translate': 3,
            'scale': 3, 'rotatex': 1, 'rotatey': 1, 'rotatez': 1,
            'rotate': 4, 'lookat': 5, 'frustum': 6, 'ortho': 6}

    def run(self, cmd, args):
        """Do one command; False if it is not supported."""
        if cmd not in self.ARGS:
            return False
        if len(args) < self.ARGS[cmd]:
            raise ValueError(f'{self.ARGS[cmd]} arguments expected')
        nums = lambda: [float(a) for a in args]
        if cmd == 'png':
            self.image = Image(int(args[0]), int(args[1]), args[2],
                               self.depth_reversed)
            self.images.append(self.image)
        elif cmd == 'xyz':
            self.vertices.append(nums()[:3] + [1.0] + self.color)
        elif cmd == 'xyzw':
            self.vertices.append(nums()[:4] + self.color)
        elif cmd == 'color':
            self.color = [min(1.0, max(0.0, c)) for c in nums()[:3]]
        elif cmd in ('trif', 'trig'):
            self.triangle([self.vertex(i) for i in args[:3]], cmd == 'trig')
        elif cmd in ('rectbezf', 'rectbezg'):
            self.rectbez(args, cmd == 'rectbezg')
        elif cmd == 'clipplane':
            self.planes.append(nums()[:4])
        elif cmd == 'cull':
            self.cull = True
        elif cmd == 'loadmv':
            self.mv = from_row_major(nums()[:16])
        elif cmd == 'loadp':
            self.proj = from_row_major(nums()[:16])
        elif cmd == 'multmv':
            if not self.ignore_multmv:
                self.add_mv(from_row_major(nums()[:16]))
        elif cmd == 'translate':
            self.add_mv(translate(*nums()[:3]))
        elif cmd == 'scale':
            self.add_mv(scale(*nums()[:3]))
        elif cmd == 'rotatex':
            self.add_mv(rotate(nums()[0], 1, 0, 0))
        elif cmd == 'rotatey':
            self.add_mv(rotate(nums()[0], 0, 1, 0))
        elif cmd == 'rotatez':
            self.add_mv(rotate(nums()[0], 0, 0, 1))
        elif cmd == 'rotate':
            self.add_mv(rotate(*nums()[:4]))
        elif cmd == 'lookat':
            eye, center = [self.point3(i) for i in args[:2]]
            self.mv = lookat(eye, center, [float(a) for a in args[2:5]])
        elif cmd == 'frustum':
            self.proj = frustum(*nums()[:6])
        elif cmd == 'ortho':
            self.proj = ortho(*nums()[:6])
        else:
            return False
        return True


def main(argv):
    ignore_multmv = '--ignore-multmv' in argv
    depth_reversed = '--depth-reversed' in argv
    files = [a for a in argv[1:] if not a.startswith('--')]
    if len(files) != 1:
        print('usage: rasterizer.py FILE.txt [--ignore-multmv] '
              '[--depth-reversed]', file=sys.stderr)
        return 2
    r = Rasterizer(ignore_multmv, depth_reversed)
    with open(files[0]) as f:
        lines = f.read().splitlines()
    status = 0
    for number, line in enumerate(lines, 1):
        words = line.split()
        if not words:
            continue
        try:
            if not r.run(words[0], words[1:]):
                print(f'{files[0]}:{number}: unsupported command {words[0]}',
                      file=sys.stderr)
        except (ValueError, IndexError, ZeroDivisionError) as e:
            print(f'{files[0]}:{number}: bad {words[0]} line ({e})',
                  file=sys.stderr)
            status = 1
    for image in r.images:
        write_png(image.filename, image.width, image.height, image.rgba)
    return status


if __name__ == '__main__':
    sys.exit(main(sys.argv))
