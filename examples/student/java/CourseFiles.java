import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Readers for the course's input files: camera, lighting and .byu object.
 * Lines may end in CRLF or LF, blank lines and tabs are allowed, numbers may have
 * exponents (9.5e-005). Double.parseDouble always uses '.', whatever the locale.
 * Warnings go to standard error.
 */
public final class CourseFiles {
    private CourseFiles() {}

    /** Camera: position C, view direction N, up hint V, and d hx hy. */
    public static class Camera {
        public double[] C, N, V;
        public double d, hx, hy;
    }

    /** One point light and the object's material (seed 000: a single light). */
    public static class Lighting {
        public double[] Pl;            // light position (world, then view coordinates)
        public double ka;              // ambient coefficient
        public double[] Ia;            // ambient colour, 0..255
        public double[] kd;            // diffuse coefficient (the same value three times for UFPE files)
        public double[] Od;            // diffuse colour, 0..1
        public double ks;              // specular coefficient
        public double[] Il;            // light colour, 0..255
        public double n;               // shininess ("constante de rugosidade")
    }

    /** Triangle mesh: vertices in world coordinates, triangles with 0-based indices. */
    public static class Mesh {
        public double[][] vertices;
        public int[][] triangles;
    }

    static void warn(String msg) {
        System.err.println("warning: " + msg);
    }

    /** A non-blank line of a file, split into words. */
    private static class Line {
        final int number;      // 1-based line number in the file
        final String text;
        final String[] words;

        Line(int number, String text) {
            this.number = number;
            this.text = text;
            String t = text.trim();
            this.words = t.isEmpty() ? new String[0] : t.split("\\s+");
        }
    }

    private static List<Line> readLines(String path) throws IOException {
        String all = new String(Files.readAllBytes(Path.of(path)), StandardCharsets.ISO_8859_1);
        if (all.startsWith("\u00ef\u00bb\u00bf")) { // UTF-8 byte order mark
            all = all.substring(3);
        }
        String[] raw = all.split("\r\n|\r|\n", -1);
        List<Line> lines = new ArrayList<>();
        for (int i = 0; i < raw.length; i++) {
            Line l = new Line(i + 1, raw[i]);
            if (l.words.length > 0) {
                lines.add(l);
            }
        }
        return lines;
    }

    private static double number(String word, String path, int line) {
        try {
            return Double.parseDouble(word);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(path + ":" + line + ": not a number: '" + word + "'");
        }
    }

    private static double[] numbers(Line l, String path) {
        double[] v = new double[l.words.length];
        for (int i = 0; i < v.length; i++) {
            v[i] = number(l.words[i], path, l.number);
        }
        return v;
    }

    private static boolean isKeyValue(List<Line> lines) {
        for (Line l : lines) {
            if (l.text.contains("=")) {
                return true;
            }
        }
        return false;
    }

    /** key = value lines: key (lower case) to its numbers. */
    private static Map<String, double[]> keyValues(List<Line> lines, String path) {
        Map<String, double[]> map = new HashMap<>();
        for (Line l : lines) {
            int eq = l.text.indexOf('=');
            if (eq < 0) {
                throw new IllegalArgumentException(path + ":" + l.number + ": expected 'key = value'");
            }
            String key = l.text.substring(0, eq).trim().toLowerCase(Locale.ROOT);
            Line value = new Line(l.number, l.text.substring(eq + 1));
            map.put(key, numbers(value, path));
        }
        return map;
    }

    private static double[] need(Map<String, double[]> map, String key, int count, String path) {
        double[] v = map.get(key.toLowerCase(Locale.ROOT));
        if (v == null) {
            throw new IllegalArgumentException(path + ": missing '" + key + " = ...'");
        }
        if (v.length != count) {
            throw new IllegalArgumentException(path + ": '" + key + "' needs " + count + " numbers, has " + v.length);
        }
        return v;
    }

    private static String pattern(List<double[]> rows) {
        StringBuilder sb = new StringBuilder();
        for (double[] r : rows) {
            sb.append(r.length);
        }
        return sb.toString();
    }

    private static double[] vec(double[] a, int from) {
        return new double[] {a[from], a[from + 1], a[from + 2]};
    }

    // ------------------------------------------------------------------ camera

    /**
     * UFPE camera (C; N; V; d hx hy), or the UFRPE layouts (N; V; d; hx; hy; C),
     * (C; N; V; hx hy; d) and key = value lines.
     */
    public static Camera readCamera(String path) throws IOException {
        List<Line> lines = readLines(path);
        Camera cam = new Camera();
        if (isKeyValue(lines)) {
            Map<String, double[]> kv = keyValues(lines, path);
            cam.C = need(kv, "C", 3, path);
            cam.N = need(kv, "N", 3, path);
            cam.V = need(kv, "V", 3, path);
            cam.d = need(kv, "d", 1, path)[0];
            cam.hx = need(kv, "hx", 1, path)[0];
            cam.hy = need(kv, "hy", 1, path)[0];
            System.err.println("camera: " + path + " read as key = value lines");
        } else {
            List<double[]> rows = new ArrayList<>();
            for (Line l : lines) {
                rows.add(numbers(l, path));
            }
            String p = pattern(rows);
            if (p.startsWith("3333")) {
                cam.C = rows.get(0); cam.N = rows.get(1); cam.V = rows.get(2);
                cam.d = rows.get(3)[0]; cam.hx = rows.get(3)[1]; cam.hy = rows.get(3)[2];
                if (rows.size() > 4) warn(path + ": lines after 'd hx hy' ignored");
            } else if (p.startsWith("331113")) {
                cam.N = rows.get(0); cam.V = rows.get(1);
                cam.d = rows.get(2)[0]; cam.hx = rows.get(3)[0]; cam.hy = rows.get(4)[0];
                cam.C = rows.get(5);
                System.err.println("camera: " + path + " read as UFRPE (N; V; d; hx; hy; C)");
            } else if (p.startsWith("33321")) {
                cam.C = rows.get(0); cam.N = rows.get(1); cam.V = rows.get(2);
                cam.hx = rows.get(3)[0]; cam.hy = rows.get(3)[1]; cam.d = rows.get(4)[0];
                System.err.println("camera: " + path + " read as UFRPE (C; N; V; hx hy; d)");
            } else {
                throw new IllegalArgumentException(path + ": unknown camera layout (numbers per line: " + p
                    + "); expected C; N; V; d hx hy (UFPE)");
            }
        }
        if (cam.d == 0 || cam.hx == 0 || cam.hy == 0) {
            throw new IllegalArgumentException(path + ": d, hx and hy must not be zero");
        }
        if (cam.hx < 0 || cam.hy < 0) {
            warn(path + ": negative hx or hy: the image is mirrored, as the formula says");
        }
        return cam;
    }

    // ---------------------------------------------------------------- lighting

    /**
     * UFPE iluminacao.txt (Pl; ka; Ia; kd; Od; ks; Il; n), UFPE multi_iluminacao.txt with one
     * light, UFRPE (Iamb Ka Il Pl Kd(3) Od Ks n) and key = value lines. The flavour is told by
     * the count of numbers (16, 11 + 6 L, 18) or by an '='.
     */
    public static Lighting readLighting(String path) throws IOException {
        List<Line> lines = readLines(path);
        Lighting l = new Lighting();
        if (isKeyValue(lines)) {
            Map<String, double[]> kv = keyValues(lines, path);
            l.Ia = need(kv, "Iamb", 3, path);
            l.ka = need(kv, "Ka", 1, path)[0];
            l.Il = need(kv, "Il", 3, path);
            l.Pl = need(kv, "Pl", 3, path);
            double[] kd = kv.get("kd");
            if (kd == null || (kd.length != 1 && kd.length != 3)) {
                throw new IllegalArgumentException(path + ": 'Kd' needs 1 or 3 numbers");
            }
            l.kd = kd.length == 1 ? new double[] {kd[0], kd[0], kd[0]} : kd;
            l.Od = need(kv, "Od", 3, path);
            l.ks = need(kv, "Ks", 1, path)[0];
            l.n = kv.containsKey("eta") ? need(kv, "eta", 1, path)[0] : need(kv, "n", 1, path)[0];
            System.err.println("lighting: " + path + " read as key = value lines");
            return l;
        }
        List<Double> all = new ArrayList<>();
        for (Line line : lines) {
            for (double x : numbers(line, path)) {
                all.add(x);
            }
        }
        double[] a = new double[all.size()];
        for (int i = 0; i < a.length; i++) {
            a[i] = all.get(i);
        }
        if (a.length == 16) {
            // UFPE: Pl(3) ka Ia(3) kd Od(3) ks Il(3) n
            l.Pl = vec(a, 0);
            l.ka = a[3];
            l.Ia = vec(a, 4);
            l.kd = new double[] {a[7], a[7], a[7]};
            l.Od = vec(a, 8);
            l.ks = a[11];
            l.Il = vec(a, 12);
            l.n = a[15];
        } else if (a.length == 18) {
            // UFRPE: Iamb(3) Ka Il(3) Pl(3) Kd(3) Od(3) Ks n
            l.Ia = vec(a, 0);
            l.ka = a[3];
            l.Il = vec(a, 4);
            l.Pl = vec(a, 7);
            l.kd = vec(a, 10);
            l.Od = vec(a, 13);
            l.ks = a[16];
            l.n = a[17];
            System.err.println("lighting: " + path + " read as UFRPE (Iamb Ka Il Pl Kd Od Ks n)");
        } else if (a.length >= 17 && a[10] == Math.rint(a[10]) && a.length == 11 + 6 * (int) a[10]) {
            // UFPE multi: ka Ia(3) kd Od(3) ks n L, then L times Pl(3) Il(3)
            int lights = (int) a[10];
            if (lights != 1) {
                throw new IllegalArgumentException(path + ": " + lights
                    + " lights; seed 000 has exactly one point light");
            }
            l.ka = a[0];
            l.Ia = vec(a, 1);
            l.kd = new double[] {a[4], a[4], a[4]};
            l.Od = vec(a, 5);
            l.ks = a[8];
            l.n = a[9];
            l.Pl = vec(a, 11);
            l.Il = vec(a, 14);
            System.err.println("lighting: " + path + " read as UFPE multi-light with one light");
        } else {
            throw new IllegalArgumentException(path + ": " + a.length
                + " numbers: not a lighting file I know (UFPE has 16: Pl ka Ia kd Od ks Il n)");
        }
        return l;
    }

    // ------------------------------------------------------------------ object

    /** The course's .byu: "nVerts nTris", the vertices, then 1-based triangles. */
    public static Mesh readByu(String path) throws IOException {
        List<Line> lines = readLines(path);
        if (lines.isEmpty()) {
            throw new IllegalArgumentException(path + ": empty file");
        }
        double[] header = numbers(lines.get(0), path);
        if (header.length == 4) {
            throw new IllegalArgumentException(path + ": the header has four numbers: this looks like an"
                + " original Movie.BYU file (parts, vertices, polygons, edges), not the course's .byu");
        }
        if (header.length != 2 || header[0] != Math.rint(header[0]) || header[1] != Math.rint(header[1])
                || header[0] < 0 || header[1] < 0) {
            throw new IllegalArgumentException(path + ":" + lines.get(0).number
                + ": expected the header 'nVertices nTriangles'");
        }
        int nv = (int) header[0];
        int nt = (int) header[1];
        if (lines.size() > 1 && lines.get(1).words.length < 3) {
            throw new IllegalArgumentException(path + ": the second line has " + lines.get(1).words.length
                + " number(s): this looks like a course Bezier surface (degrees, evaluations, control"
                + " points), which this program does not read");
        }
        if (lines.size() < 1 + nv + nt) {
            throw new IllegalArgumentException(path + ": the header declares " + nv + " vertices and " + nt
                + " triangles, but the file has only " + (lines.size() - 1) + " data lines");
        }
        Mesh m = new Mesh();
        m.vertices = new double[nv][];
        for (int i = 0; i < nv; i++) {
            Line l = lines.get(1 + i);
            double[] p = numbers(l, path);
            if (p.length != 3) {
                throw new IllegalArgumentException(path + ":" + l.number + ": a vertex needs 3 numbers, found "
                    + p.length);
            }
            m.vertices[i] = p;
        }
        m.triangles = new int[nt][3];
        for (int t = 0; t < nt; t++) {
            Line l = lines.get(1 + nv + t);
            double[] ids = numbers(l, path);
            if (ids.length != 3) {
                throw new IllegalArgumentException(path + ":" + l.number + ": a triangle needs 3 indices, found "
                    + ids.length + (ids.length > 3 ? " (polygons with more than 3 vertices are not read)" : ""));
            }
            for (int k = 0; k < 3; k++) {
                double id = ids[k];
                if (id != Math.rint(id) || id < 1 || id > nv) {
                    String hint = id == 0 ? " (0-based indices? the course counts from 1)"
                        : id < 0 ? " (negative: a Movie.BYU polygon end?)" : "";
                    throw new IllegalArgumentException(path + ":" + l.number + ": vertex index " + l.words[k]
                        + " is not in 1.." + nv + hint);
                }
                m.triangles[t][k] = (int) id - 1;
            }
        }
        int extra = lines.size() - (1 + nv + nt);
        if (extra > 0) {
            warn(path + ": " + extra + " line(s) after the declared " + nv + " vertices and " + nt
                + " triangles were ignored (read exactly the header's counts)");
        }
        return m;
    }
}
