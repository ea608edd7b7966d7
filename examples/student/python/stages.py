#!/usr/bin/env python3
"""rasterizer.py's stages, answered over RasterLab's stage protocol.

    rasterlab-cli check --program "python3 stages.py [mistakes]"

RasterLab writes each request on standard input (docs/stage-protocol.md); each
answer comes from rasterizer.py's own functions, the ones its render calls.
rasterizer.py's mistake switches work here too, so that `check` can be tried
on a renderer with a known mistake.
"""

import argparse
import sys

import rasterizer as r

LISTS = {"vertices", "triangles", "fragments", "samples"}


def read_request(stdin):
    """The records of one request up to 'end': name -> numbers, and for the
    lists name -> rows."""
    records = {}
    for line in stdin:
        fields = line.split()
        if fields[0] == "end":
            return records
        numbers = [float(x) for x in fields[1:]]
        if fields[0] in LISTS:
            count = int(numbers[0])
            numbers = [[float(x) for x in next(stdin).split()]
                       for _ in range(count)]
        records[fields[0]] = numbers
    return records


def write(*records):
    """Each record a line: a name, then numbers (repr: read back exactly)."""
    out = []
    for name, *numbers in records:
        out.append(" ".join([name] + [repr(v) for v in numbers]))
    return out


def write_list(name, rows):
    return [f"{name} {len(rows)}"] + [" ".join(repr(v) for v in row)
                                       for row in rows]


def lighting_of(q):
    light = {"Ia": tuple(q["Ia"]), "Il": tuple(q["Il"]), "ka": q["ka"][0],
             "kd": q["kd"][0], "Od": tuple(q["Od"]), "ks": q["ks"][0],
             "n": q["n"][0]}
    return light, tuple(q["light"])


def triangles_of(q):
    return [tuple(int(i) for i in t) for t in q["triangles"]]


def answer(stage, q, opts):
    if stage == "basis":
        U, V, N = r.camera_basis(tuple(q["N"]), tuple(q["V"]), opts)
        return write(("U", *U), ("V", *V), ("N", *N))
    if stage == "view":
        I, C = (q["U"], q["V"], q["N"]), tuple(q["C"])
        light = r.light_in_view(I, tuple(q["light"]), C, opts)
        points = [r.to_view(I, P, C) for P in q["vertices"]]
        return write(("light", *light)) + write_list("vertices", points)
    if stage == "normals":
        points = [tuple(p) for p in q["vertices"]]
        triangles = triangles_of(q)
        faces = [r.triangle_normal(*(points[i] for i in t), opts)
                 for t in triangles]
        vertices = r.vertex_normals(points, points, triangles, opts)
        return (write_list("triangle-normals", faces) +
                write_list("vertex-normals", vertices))
    if stage == "projection":
        d, hx, hy = q["camera"]
        w, h = (int(v) for v in q["size"])
        camera = {"d": d, "hx": hx, "hy": hy}
        return write_list("screen", [r.project(P, camera, w, h, opts)
                                     for P in q["vertices"]])
    if stage == "scan":
        w, h = (int(v) for v in q["size"])
        spans = []
        for t, v in enumerate(q["triangles"]):
            screen = [(int(v[0]), int(v[1])), (int(v[2]), int(v[3])),
                      (int(v[4]), int(v[5]))]
            spans += [(t, y, x0, x1)
                      for y, x0, x1 in r.triangle_spans(screen, w, h, opts)]
        return write_list("spans", spans)
    if stage == "zbuffer":
        w, h = (int(v) for v in q["size"])
        frame = r.Frame(w, h, opts)
        winner = {}
        for t, x, y, z in q["fragments"]:
            index = int(y) * w + int(x)
            if frame.closer(z, index):
                frame.zbuffer[index] = z
                winner[index] = int(t)
        return write_list("pixels", [(i % w, i // w, t, frame.zbuffer[i])
                                     for i, t in sorted(winner.items())])
    if stage == "lighting":
        light, Pl = lighting_of(q)
        colours = []
        for px, py, pz, nx, ny, nz in q["samples"]:
            c = r.phong((px, py, pz), (nx, ny, nz), light, Pl, opts)
            colours.append(c if opts.no_clamp else
                           tuple(min(v, 255.0) for v in c))
        return write_list("colours", colours)
    if stage == "frame":
        w, h = (int(v) for v in q["size"])
        d, hx, hy = q["camera"]
        camera = {"C": tuple(q["C"]), "N": tuple(q["N"]), "V": tuple(q["V"]),
                  "d": d, "hx": hx, "hy": hy}
        light, Pl = lighting_of(q)
        light["Pl"] = Pl
        frame = r.render(camera, light, [tuple(p) for p in q["vertices"]],
                         triangles_of(q), w, h, opts)
        rows = [" ".join(str(b) for b in frame.pixels[3 * w * y:3 * w * (y + 1)])
                for y in range(h)]
        return [f"image {w} {h}"] + rows
    return None


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    r.add_mistakes(parser)
    opts = parser.parse_args(argv)
    stdin = iter(sys.stdin.readline, "")
    if next(stdin).split() != ["rasterlab", "1"]:
        sys.exit("stages.py speaks the stage protocol's version 1")
    print("speaks 1", flush=True)
    for line in stdin:
        stage = line.strip()
        if stage == "bye":
            return 0
        lines = answer(stage, read_request(stdin), opts)
        print("\n".join(["unsupported"] if lines is None else lines + ["end"]),
              flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
