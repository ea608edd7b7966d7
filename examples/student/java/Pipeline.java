import java.util.ArrayList;
import java.util.List;

/**
 * Seed 000, step by step. Render calls render(); Stages calls each step on its own.
 * The mistake switches (Switches) change the step where the mistake lives.
 */
public class Pipeline {
    private final Switches sw;

    public Pipeline(Switches sw) {
        this.sw = sw;
    }

    // ------------------------------------------------------------ 1. Gram-Schmidt

    /** alfa = {U, V, N}: the rows of the change-of-basis matrix [I]e,alfa. */
    public static class Basis {
        public final double[] U, V, N;

        Basis(double[] U, double[] V, double[] N) {
            this.U = U;
            this.V = V;
            this.N = N;
        }
    }

    /** Normalise N, V = V - proj_N(V), normalise V, U = N x V. */
    public Basis gramSchmidt(double[] cameraN, double[] cameraV) {
        if (sw.gramSchmidtFloat) {
            return gramSchmidtFloat(cameraN, cameraV);
        }
        double[] N = cameraN.clone();
        if (sw.nNormalisation == Switches.NNormalisation.FIRST) {
            N = Vec.normalize(N);
        }
        // V = V - proj N (V)
        double vn = Vec.dot(cameraV, N);
        double[] V = Vec.sub(cameraV, Vec.scale(N, vn));
        if (sw.nNormalisation == Switches.NNormalisation.AFTER) {
            N = Vec.normalize(N);
        }
        V = Vec.normalize(V);
        double[] U = Vec.cross(N, V);
        return new Basis(U, V, N);
    }

    /** My first version of the basis, with float variables. */
    private Basis gramSchmidtFloat(double[] cameraN, double[] cameraV) {
        float nx = (float) cameraN[0], ny = (float) cameraN[1], nz = (float) cameraN[2];
        float vx = (float) cameraV[0], vy = (float) cameraV[1], vz = (float) cameraV[2];
        if (sw.nNormalisation == Switches.NNormalisation.FIRST) {
            float nlen = (float) Math.sqrt(nx * nx + ny * ny + nz * nz);
            nx = nx / nlen;
            ny = ny / nlen;
            nz = nz / nlen;
        }
        // V = V - proj N (V)
        float vn = vx * nx + vy * ny + vz * nz;
        vx = vx - vn * nx;
        vy = vy - vn * ny;
        vz = vz - vn * nz;
        if (sw.nNormalisation == Switches.NNormalisation.AFTER) {
            float nlen = (float) Math.sqrt(nx * nx + ny * ny + nz * nz);
            nx = nx / nlen;
            ny = ny / nlen;
            nz = nz / nlen;
        }
        float vlen = (float) Math.sqrt(vx * vx + vy * vy + vz * vz);
        vx = vx / vlen;
        vy = vy / vlen;
        vz = vz / vlen;
        // U = N x V
        float ux = ny * vz - nz * vy;
        float uy = nz * vx - nx * vz;
        float uz = nx * vy - ny * vx;
        return new Basis(new double[] {ux, uy, uz}, new double[] {vx, vy, vz}, new double[] {nx, ny, nz});
    }

    // ------------------------------------------------------- 2. view coordinates

    /** P_vista = [I]e,alfa * (P - C). */
    public double[] toView(Basis b, double[] C, double[] P) {
        double[] d = Vec.sub(P, C);
        return new double[] {Vec.dot(b.U, d), Vec.dot(b.V, d), Vec.dot(b.N, d)};
    }

    /** Pl_vista = [I]e,alfa * (Pl - C), written over Pl ("podendo descartar o Pl original"). */
    public void moveLightToView(Basis b, double[] C, double[] Pl) {
        if (sw.lightInPlace) {
            Pl[0] = b.U[0] * (Pl[0] - C[0]) + b.U[1] * (Pl[1] - C[1]) + b.U[2] * (Pl[2] - C[2]);
            Pl[1] = b.V[0] * (Pl[0] - C[0]) + b.V[1] * (Pl[1] - C[1]) + b.V[2] * (Pl[2] - C[2]);
            Pl[2] = b.N[0] * (Pl[0] - C[0]) + b.N[1] * (Pl[1] - C[1]) + b.N[2] * (Pl[2] - C[2]);
            return;
        }
        double x = b.U[0] * (Pl[0] - C[0]) + b.U[1] * (Pl[1] - C[1]) + b.U[2] * (Pl[2] - C[2]);
        double y = b.V[0] * (Pl[0] - C[0]) + b.V[1] * (Pl[1] - C[1]) + b.V[2] * (Pl[2] - C[2]);
        double z = b.N[0] * (Pl[0] - C[0]) + b.N[1] * (Pl[1] - C[1]) + b.N[2] * (Pl[2] - C[2]);
        Pl[0] = x;
        Pl[1] = y;
        Pl[2] = z;
    }

    // ----------------------------------------------------------------- 3. normals

    /** (Pb - Pa) x (Pc - Pa), normalised; 0 0 0 for a triangle of zero area. */
    public double[] triangleNormal(double[] pa, double[] pb, double[] pc) {
        return Vec.normalize(Vec.cross(Vec.sub(pb, pa), Vec.sub(pc, pa)));
    }

    public double[][] triangleNormals(double[][] view, int[][] triangles) {
        double[][] normals = new double[triangles.length][];
        for (int t = 0; t < triangles.length; t++) {
            int[] tri = triangles[t];
            normals[t] = triangleNormal(view[tri[0]], view[tri[1]], view[tri[2]]);
        }
        return normals;
    }

    /** Start at zero, add each triangle's unit normal to its 3 vertices, normalise all. */
    public double[][] vertexNormals(double[][] view, int[][] triangles, double[][] triNormals) {
        double[][] normals = new double[view.length][3];
        for (int t = 0; t < triangles.length; t++) {
            int[] tri = triangles[t];
            if (sw.vertexNormalsFrontOnly) {
                // only the triangles facing the camera: normal . (-P1) > 0
                if (Vec.dot(triNormals[t], Vec.neg(view[tri[0]])) <= 0) {
                    continue;
                }
            }
            for (int k = 0; k < 3; k++) {
                double[] n = normals[tri[k]];
                n[0] += triNormals[t][0];
                n[1] += triNormals[t][1];
                n[2] += triNormals[t][2];
            }
        }
        for (int i = 0; i < normals.length; i++) {
            normals[i] = Vec.normalize(normals[i]);
        }
        return normals;
    }

    // -------------------------------------------------------------- 4. projection

    /** View coordinates to the screen: [-1, 1] first, then pixels, made whole. */
    public double[] toScreen(double[] P, double d, double hx, double hy, int width, int height) {
        double px = (d / hx) * (P[0] / P[2]);
        double py = (d / hy) * (P[1] / P[2]);
        double x = (px + 1) * width / 2;
        double y = (1 - py) * height / 2;
        switch (sw.rounding) {
            case CAST:
                return new double[] {(int) x, (int) y};
            case FLOOR:
                return new double[] {Math.floor(x), Math.floor(y)};
            case CEIL:
                return new double[] {Math.ceil(x), Math.ceil(y)};
            default: // NONE: the student forgot the cast
                return new double[] {x, y};
        }
    }

    // --------------------------------------------------------- 5. scan conversion

    /** Pixels first..last (both included) of row y. */
    public static class Span {
        public final int y, first, last;

        Span(int y, int first, int last) {
            this.y = y;
            this.first = first;
            this.last = last;
        }
    }

    // Per-row tables of the current triangle, one entry per screen row.
    private double[] rowLeft = new double[0];
    private double[] rowRight = new double[0];

    /** x where the edge p-q crosses row y (the edge is not horizontal). */
    private double edgeCrossing(double[] p, double[] q, double y) {
        if (sw.edgesYaxb) {
            if (p[0] == q[0]) {
                return p[0]; // vertical edge
            }
            double a = (q[1] - p[1]) / (q[0] - p[0]);
            double b = p[1] - a * p[0];
            return (y - b) / a;
        }
        return p[0] + (y - p[1]) * (q[0] - p[0]) / (q[1] - p[1]);
    }

    /** First row at or below y (ceil), kept in int range. */
    private static int ceilRow(double y) {
        return (int) Math.max(Math.min(Math.ceil(y), 1e9), -1e9);
    }

    private static int floorRow(double y) {
        return (int) Math.max(Math.min(Math.floor(y), 1e9), -1e9);
    }

    /**
     * The pixels inside the triangle a b c (screen coordinates): a pixel (x, y) is sampled at the
     * point (x, y) and a sample on an edge is inside. Each row of the triangle gets the leftmost and
     * rightmost edge crossings in rowLeft/rowRight; the span is ceil(left)..floor(right).
     * Only pixels on the screen are returned.
     */
    public List<Span> scanTriangle(double[] a, double[] b, double[] c, int width, int height) {
        List<Span> spans = new ArrayList<>();
        double[][] v = {a, b, c};
        for (double[] p : v) {
            if (!Double.isFinite(p[0]) || !Double.isFinite(p[1])) {
                return spans; // a vertex at the eye: nothing sensible to draw
            }
        }
        double area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
        if (area == 0) {
            return spans;
        }
        if (rowLeft.length != height) {
            rowLeft = new double[height];
            rowRight = new double[height];
        }
        int top = ceilRow(Math.min(a[1], Math.min(b[1], c[1])));
        int bottom = floorRow(Math.max(a[1], Math.max(b[1], c[1])));
        if (!sw.scanIndexBug) {
            top = Math.max(top, 0);
            bottom = Math.min(bottom, height - 1);
        }
        for (int y = top; y <= bottom; y++) {
            rowLeft[y] = Double.POSITIVE_INFINITY;
            rowRight[y] = Double.NEGATIVE_INFINITY;
        }
        // walk the three edges; a horizontal edge is skipped: its two ends are ends of the others
        for (int e = 0; e < 3; e++) {
            double[] p = v[e];
            double[] q = v[(e + 1) % 3];
            if (p[1] == q[1]) {
                continue;
            }
            int y0 = ceilRow(Math.min(p[1], q[1]));
            int y1 = floorRow(Math.max(p[1], q[1]));
            if (!sw.scanIndexBug) {
                y0 = Math.max(y0, 0);
                y1 = Math.min(y1, height - 1);
            }
            for (int y = y0; y <= y1; y++) {
                double x = edgeCrossing(p, q, y);
                rowLeft[y] = Math.min(rowLeft[y], x);
                rowRight[y] = Math.max(rowRight[y], x);
            }
        }
        for (int y = Math.max(top, 0); y <= Math.min(bottom, height - 1); y++) {
            if (rowLeft[y] > rowRight[y]) {
                continue;
            }
            int first = (int) Math.max(Math.ceil(rowLeft[y]), 0);
            int last = (int) Math.min(Math.floor(rowRight[y]), width - 1);
            if (first <= last) {
                spans.add(new Span(y, first, last));
            }
        }
        return spans;
    }

    /** Barycentric coordinates (alfa, beta, gama) of (x, y) in the 2D triangle a b c. */
    public double[] barycentric(double x, double y, double[] a, double[] b, double[] c) {
        double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
        double beta = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / det;
        double gama = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / det;
        double alfa = 1 - beta - gama;
        return new double[] {alfa, beta, gama};
    }

    /** alfa*p1 + beta*p2 + gama*p3. */
    public static double[] interpolate(double[] bar, double[] p1, double[] p2, double[] p3) {
        return new double[] {
            bar[0] * p1[0] + bar[1] * p2[0] + bar[2] * p3[0],
            bar[0] * p1[1] + bar[1] * p2[1] + bar[2] * p3[1],
            bar[0] * p1[2] + bar[1] * p2[2] + bar[2] * p3[2]
        };
    }

    // ------------------------------------------------------------------ 6. z-buffer

    /** z-buffer[width][height], +infinity everywhere, and which triangle each pixel keeps. */
    public static class ZBuffer {
        public final int width, height;
        public final double[][] depth;
        public final int[][] triangle;

        public ZBuffer(int width, int height) {
            this.width = width;
            this.height = height;
            depth = new double[width][height];
            triangle = new int[width][height];
            for (int x = 0; x < width; x++) {
                for (int y = 0; y < height; y++) {
                    depth[x][y] = Double.POSITIVE_INFINITY;
                    triangle[x][y] = -1;
                }
            }
        }

        /** Keeps the fragment when it is nearer (z smaller) than what is stored; on a tie the old one stays. */
        public boolean test(int x, int y, double z, int t) {
            if (x < 0 || x >= width || y < 0 || y >= height) {
                return false;
            }
            if (z < depth[x][y]) {
                depth[x][y] = z;
                triangle[x][y] = t;
                return true;
            }
            return false;
        }
    }

    // ------------------------------------------------------------------ 7. Phong

    /** The colour at P' (view coordinates) with normal N, light at Pl (view coordinates). */
    public double[] phong(double[] P, double[] normal, double[] Pl, CourseFiles.Lighting l) {
        double[] N = Vec.normalize(normal);
        double[] V = Vec.normalize(Vec.neg(P));
        double[] L = Vec.normalize(Vec.sub(Pl, P));
        if (Vec.dot(V, N) < 0) {
            N = Vec.neg(N);
        }
        double[] I = new double[3];
        for (int c = 0; c < 3; c++) {
            I[c] = l.Ia[c] * l.ka;
        }
        double nl = Vec.dot(N, L);
        if (sw.specularWithoutNlTest) {
            // diffuse clamped at zero, specular only tested with R . V
            for (int c = 0; c < 3; c++) {
                I[c] += l.Il[c] * l.Od[c] * l.kd[c] * Math.max(0, nl);
            }
            double[] R = Vec.normalize(Vec.sub(Vec.scale(N, 2 * nl), L));
            double rv = Vec.dot(R, V);
            if (rv > 0) {
                for (int c = 0; c < 3; c++) {
                    I[c] += l.Il[c] * l.ks * Math.pow(rv, l.n);
                }
            }
        } else if (nl >= 0) {
            // N . L < 0: neither diffuse nor specular
            for (int c = 0; c < 3; c++) {
                I[c] += l.Il[c] * l.Od[c] * l.kd[c] * nl;
            }
            double[] R = Vec.normalize(Vec.sub(Vec.scale(N, 2 * nl), L));
            double rv = Vec.dot(R, V);
            if (rv >= 0) {
                for (int c = 0; c < 3; c++) {
                    I[c] += l.Il[c] * l.ks * Math.pow(rv, l.n);
                }
            }
        }
        for (int c = 0; c < 3; c++) {
            I[c] = Math.min(I[c], 255);
        }
        return I;
    }

    // ------------------------------------------------------------ the whole seed

    /** Set by Render: leave out the triangles with a vertex at or behind the camera (z <= 0). */
    public boolean skipBehindCamera = false;

    /**
     * Renders the scene into rgb[height][width][3] (0..255, black background).
     * The lighting's Pl is moved to view coordinates in place.
     */
    public int[][][] render(CourseFiles.Camera cam, CourseFiles.Lighting light, CourseFiles.Mesh mesh,
                            int width, int height) {
        Basis basis = gramSchmidt(cam.N, cam.V);
        moveLightToView(basis, cam.C, light.Pl);

        double[][] view = new double[mesh.vertices.length][];
        for (int i = 0; i < view.length; i++) {
            view[i] = toView(basis, cam.C, mesh.vertices[i]);
        }
        double[][] triNormals = triangleNormals(view, mesh.triangles);
        double[][] vertNormals = vertexNormals(view, mesh.triangles, triNormals);

        double[][] screen = new double[view.length][];
        int behind = 0;
        for (int i = 0; i < view.length; i++) {
            screen[i] = toScreen(view[i], cam.d, cam.hx, cam.hy, width, height);
            if (view[i][2] <= 0) {
                behind++;
            }
        }
        if (behind > 0) {
            System.err.println("warning: " + behind + " of " + view.length + " vertices are at or behind the camera"
                + (skipBehindCamera ? "; their triangles are not drawn" : "; drawn dividing by z as the seed does"));
        }

        ZBuffer zbuffer = new ZBuffer(width, height);
        int[][][] image = new int[height][width][3];
        int skipped = 0;
        for (int t = 0; t < mesh.triangles.length; t++) {
            int[] tri = mesh.triangles[t];
            if (skipBehindCamera && (view[tri[0]][2] <= 0 || view[tri[1]][2] <= 0 || view[tri[2]][2] <= 0)) {
                skipped++;
                continue;
            }
            double[] s1 = screen[tri[0]], s2 = screen[tri[1]], s3 = screen[tri[2]];
            for (Span span : scanTriangle(s1, s2, s3, width, height)) {
                for (int x = span.first; x <= span.last; x++) {
                    double[] bar = barycentric(x, span.y, s1, s2, s3);
                    double[] p = interpolate(bar, view[tri[0]], view[tri[1]], view[tri[2]]);
                    if (zbuffer.test(x, span.y, p[2], t)) {
                        double[] n = interpolate(bar, vertNormals[tri[0]], vertNormals[tri[1]], vertNormals[tri[2]]);
                        double[] colour = phong(p, n, light.Pl, light);
                        for (int c = 0; c < 3; c++) {
                            image[span.y][x][c] = (int) Math.max(0, colour[c]);
                        }
                    }
                }
            }
        }
        if (skipped > 0) {
            System.err.println("warning: " + skipped + " triangle(s) with a vertex at or behind the camera were not"
                + " drawn (use --naive-projection to divide by z anyway, as seed 000 does)");
        }
        return image;
    }
}
