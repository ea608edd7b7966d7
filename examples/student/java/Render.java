import java.awt.image.BufferedImage;
import java.io.File;
import javax.imageio.ImageIO;

/**
 * Renders a course scene with seed 000 and writes a PNG.
 *
 *   java -cp out Render --camera F --lighting F --object F --size WxH --output FILE [switches]
 */
public class Render {
    static void usage() {
        System.err.println("usage: java -cp out Render --camera FILE --lighting FILE --object FILE"
            + " [--size WxH] [--output FILE.png] [--naive-projection] [mistake switches]\n"
            + "  --size defaults to 800x600, --output to render.png\n"
            + "  --naive-projection  also draw triangles with a vertex at or behind the camera (divide by z)\n"
            + Switches.HELP);
    }

    public static void main(String[] args) throws Exception {
        System.setProperty("java.awt.headless", "true");
        Switches sw = new Switches();
        String camera = null, lighting = null, object = null, output = "render.png";
        int width = 800, height = 600;
        boolean naive = false;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (sw.parse(a)) {
                continue;
            }
            if (a.equals("--naive-projection")) {
                naive = true;
                continue;
            }
            if (a.equals("-h") || a.equals("--help")) {
                usage();
                return;
            }
            if (i + 1 >= args.length) {
                System.err.println("error: " + a + " needs a value (or is unknown)");
                usage();
                System.exit(2);
            }
            String value = args[++i];
            switch (a) {
                case "--camera": camera = value; break;
                case "--lighting": lighting = value; break;
                case "--object": object = value; break;
                case "--output": output = value; break;
                case "--size": {
                    String[] wh = value.toLowerCase().split("x");
                    if (wh.length != 2) {
                        System.err.println("error: --size must be WxH, e.g. 160x120");
                        System.exit(2);
                    }
                    width = Integer.parseInt(wh[0].trim());
                    height = Integer.parseInt(wh[1].trim());
                    if (width <= 0 || height <= 0) {
                        System.err.println("error: --size must be positive");
                        System.exit(2);
                    }
                    break;
                }
                default:
                    System.err.println("error: unknown option " + a);
                    usage();
                    System.exit(2);
            }
        }
        if (camera == null || lighting == null || object == null) {
            usage();
            System.exit(2);
        }
        CourseFiles.Camera cam;
        CourseFiles.Lighting light;
        CourseFiles.Mesh mesh;
        try {
            cam = CourseFiles.readCamera(camera);
            light = CourseFiles.readLighting(lighting);
            mesh = CourseFiles.readByu(object);
        } catch (IllegalArgumentException e) {
            System.err.println("error: " + e.getMessage());
            System.exit(1);
            return;
        }
        Pipeline pipeline = new Pipeline(sw);
        pipeline.skipBehindCamera = !naive;
        int[][][] image = pipeline.render(cam, light, mesh, width, height);

        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int[] c = image[y][x];
                img.setRGB(x, y, (c[0] << 16) | (c[1] << 8) | c[2]);
            }
        }
        if (!ImageIO.write(img, "png", new File(output))) {
            System.err.println("error: no PNG writer");
            System.exit(1);
        }
        System.err.println("wrote " + output + " (" + width + "x" + height + ", " + mesh.vertices.length
            + " vertices, " + mesh.triangles.length + " triangles, switches: " + sw + ")");
    }
}
