import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The stage protocol, version 1 (stage-protocol.md), around Pipeline's own functions.
 *
 *   java -cp out Stages [mistake switches]
 *
 * Requests come on standard input, answers go to standard output; messages go to standard
 * error. A crash in a stage (for instance --scan-index-bug) is not caught: the program dies
 * with the exception, as the student's program would.
 */
public class Stages {
    private final BufferedReader in;
    private final PrintWriter out;
    private final Pipeline pipeline;

    /** The records of one request: single records and lists. */
    private final Map<String, double[]> records = new HashMap<>();
    private final Map<String, double[][]> lists = new HashMap<>();

    Stages(Switches sw) {
        in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        out = new PrintWriter(new BufferedWriter(new OutputStreamWriter(System.out, StandardCharsets.UTF_8),
            1 << 16), false);
        pipeline = new Pipeline(sw);
    }

    public static void main(String[] args) throws IOException {
        Switches sw = new Switches();
        for (String a : args) {
            if (!sw.parse(a)) {
                System.err.println("unknown switch: " + a + "\n" + Switches.HELP);
                System.exit(2);
            }
        }
        System.err.println("Stages: switches " + sw);
        new Stages(sw).run();
    }

    private String[] readWords() throws IOException {
        String line = in.readLine();
        if (line == null) {
            return null;
        }
        String t = line.trim();
        return t.isEmpty() ? new String[0] : t.split("[ \t]+");
    }

    private static double[] numbers(String[] w, int from) {
        double[] v = new double[w.length - from];
        for (int i = from; i < w.length; i++) {
            v[i - from] = Double.parseDouble(w[i]);
        }
        return v;
    }

    private static boolean isList(String name) {
        return name.equals("vertices") || name.equals("triangles") || name.equals("fragments")
            || name.equals("samples");
    }

    /** Reads the records up to "end". */
    private void readRequest() throws IOException {
        records.clear();
        lists.clear();
        while (true) {
            String[] w = readWords();
            if (w == null) {
                throw new IOException("input ended inside a request");
            }
            if (w.length == 0) {
                continue;
            }
            if (w[0].equals("end")) {
                return;
            }
            if (isList(w[0])) {
                int count = Integer.parseInt(w[1]);
                double[][] rows = new double[count][];
                for (int i = 0; i < count; i++) {
                    rows[i] = numbers(readWords(), 0);
                }
                lists.put(w[0], rows);
            } else {
                records.put(w[0], numbers(w, 1));
            }
        }
    }

    void run() throws IOException {
        String[] hello = readWords();
        if (hello == null || hello.length < 2 || !hello[0].equals("rasterlab")) {
            System.err.println("Stages: expected 'rasterlab 1', got " + (hello == null ? "nothing" : String.join(" ", hello)));
            System.exit(1);
        }
        out.print("speaks 1\n");
        out.flush();
        while (true) {
            String[] w = readWords();
            if (w == null) {
                return;
            }
            if (w.length == 0) {
                continue;
            }
            String stage = w[0];
            if (stage.equals("bye")) {
                return;
            }
            readRequest();
            switch (stage) {
                case "basis": basis(); break;
                case "view": view(); break;
                case "normals": normals(); break;
                case "projection": projection(); break;
                case "scan": scan(); break;
                case "zbuffer": zbuffer(); break;
                case "lighting": lighting(); break;
                case "frame": frame(); break;
                default:
                    out.print("unsupported\n");
                    out.flush();
                    continue;
            }
            out.print("end\n");
            out.flush();
        }
    }

    // -------------------------------------------------------------- number output

    /** Shortest digits that read back as the same double (Java's), with a lower-case exponent. */
    static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        return Double.toString(v).replace('E', 'e');
    }

    private void record(String name, double... values) {
        StringBuilder sb = new StringBuilder(name);
        for (double v : values) {
            sb.append(' ').append(num(v));
        }
        sb.append('\n');
        out.print(sb);
    }

    private void row(double... values) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < values.length; i++) {
            if (i > 0) {
                sb.append(' ');
            }
            sb.append(num(values[i]));
        }
        sb.append('\n');
        out.print(sb);
    }

    private static int[][] triangles(double[][] rows) {
        int[][] t = new int[rows.length][3];
        for (int i = 0; i < rows.length; i++) {
            for (int k = 0; k < 3; k++) {
                t[i][k] = (int) rows[i][k];
            }
        }
        return t;
    }

    private CourseFiles.Lighting lightingRecords() {
        CourseFiles.Lighting l = new CourseFiles.Lighting();
        l.Pl = records.get("light").clone();
        l.Ia = records.get("Ia");
        l.Il = records.get("Il");
        l.ka = records.get("ka")[0];
        double kd = records.get("kd")[0];
        l.kd = new double[] {kd, kd, kd};
        l.Od = records.get("Od");
        l.ks = records.get("ks")[0];
        l.n = records.get("n")[0];
        return l;
    }

    // ------------------------------------------------------------------ stages

    private void basis() {
        Pipeline.Basis b = pipeline.gramSchmidt(records.get("N"), records.get("V"));
        record("U", b.U);
        record("V", b.V);
        record("N", b.N);
    }

    private void view() {
        Pipeline.Basis b = new Pipeline.Basis(records.get("U"), records.get("V"), records.get("N"));
        double[] C = records.get("C");
        double[] light = records.get("light").clone();
        pipeline.moveLightToView(b, C, light);
        record("light", light);
        double[][] vertices = lists.get("vertices");
        record("vertices", vertices.length);
        for (double[] p : vertices) {
            row(pipeline.toView(b, C, p));
        }
    }

    private void normals() {
        double[][] view = lists.get("vertices");
        int[][] tris = triangles(lists.get("triangles"));
        double[][] triNormals = pipeline.triangleNormals(view, tris);
        double[][] vertNormals = pipeline.vertexNormals(view, tris, triNormals);
        record("triangle-normals", triNormals.length);
        for (double[] n : triNormals) {
            row(n);
        }
        record("vertex-normals", vertNormals.length);
        for (double[] n : vertNormals) {
            row(n);
        }
    }

    private void projection() {
        double[] cam = records.get("camera");
        double[] size = records.get("size");
        double[][] view = lists.get("vertices");
        record("screen", view.length);
        for (double[] p : view) {
            row(pipeline.toScreen(p, cam[0], cam[1], cam[2], (int) size[0], (int) size[1]));
        }
    }

    private void scan() {
        double[] size = records.get("size");
        int width = (int) size[0], height = (int) size[1];
        double[][] tris = lists.get("triangles");
        StringBuilder sb = new StringBuilder();
        int count = 0;
        for (int t = 0; t < tris.length; t++) {
            double[] r = tris[t];
            List<Pipeline.Span> spans = pipeline.scanTriangle(new double[] {r[0], r[1]},
                new double[] {r[2], r[3]}, new double[] {r[4], r[5]}, width, height);
            for (Pipeline.Span s : spans) {
                sb.append(t).append(' ').append(s.y).append(' ').append(s.first).append(' ').append(s.last)
                    .append('\n');
                count++;
            }
        }
        record("spans", count);
        out.print(sb);
    }

    private void zbuffer() {
        double[] size = records.get("size");
        Pipeline.ZBuffer zb = new Pipeline.ZBuffer((int) size[0], (int) size[1]);
        for (double[] f : lists.get("fragments")) {
            zb.test((int) f[1], (int) f[2], f[3], (int) f[0]);
        }
        StringBuilder sb = new StringBuilder();
        int count = 0;
        for (int y = 0; y < zb.height; y++) {
            for (int x = 0; x < zb.width; x++) {
                if (zb.triangle[x][y] >= 0) {
                    sb.append(x).append(' ').append(y).append(' ').append(zb.triangle[x][y]).append(' ')
                        .append(num(zb.depth[x][y])).append('\n');
                    count++;
                }
            }
        }
        record("pixels", count);
        out.print(sb);
    }

    private void lighting() {
        CourseFiles.Lighting l = lightingRecords();
        double[][] samples = lists.get("samples");
        record("colours", samples.length);
        for (double[] s : samples) {
            double[] P = {s[0], s[1], s[2]};
            double[] N = {s[3], s[4], s[5]};
            row(pipeline.phong(P, N, l.Pl, l));
        }
    }

    private void frame() {
        double[] size = records.get("size");
        int width = (int) size[0], height = (int) size[1];
        CourseFiles.Camera cam = new CourseFiles.Camera();
        cam.C = records.get("C");
        cam.N = records.get("N");
        cam.V = records.get("V");
        double[] c = records.get("camera");
        cam.d = c[0];
        cam.hx = c[1];
        cam.hy = c[2];
        CourseFiles.Mesh mesh = new CourseFiles.Mesh();
        mesh.vertices = lists.get("vertices");
        mesh.triangles = triangles(lists.get("triangles"));
        int[][][] image = pipeline.render(cam, lightingRecords(), mesh, width, height);
        out.print("image " + width + " " + height + "\n");
        StringBuilder sb = new StringBuilder();
        for (int y = 0; y < height; y++) {
            sb.setLength(0);
            for (int x = 0; x < width; x++) {
                int[] p = image[y][x];
                if (x > 0) {
                    sb.append(' ');
                }
                sb.append(p[0]).append(' ').append(p[1]).append(' ').append(p[2]);
            }
            sb.append('\n');
            out.print(sb);
        }
    }
}
