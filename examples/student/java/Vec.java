/** Small vector helpers on double[3] arrays (x, y, z). */
public final class Vec {
    private Vec() {}

    public static double[] of(double x, double y, double z) {
        return new double[] {x, y, z};
    }

    public static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    public static double[] add(double[] a, double[] b) {
        return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    }

    public static double[] scale(double[] a, double k) {
        return new double[] {a[0] * k, a[1] * k, a[2] * k};
    }

    public static double[] neg(double[] a) {
        return new double[] {-a[0], -a[1], -a[2]};
    }

    public static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    public static double[] cross(double[] a, double[] b) {
        return new double[] {
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0]
        };
    }

    public static double length(double[] a) {
        return Math.sqrt(dot(a, a));
    }

    /** a / |a|; the zero vector stays zero (no NaN). */
    public static double[] normalize(double[] a) {
        double len = length(a);
        if (len == 0) {
            return new double[] {0, 0, 0};
        }
        return new double[] {a[0] / len, a[1] / len, a[2] / len};
    }
}
