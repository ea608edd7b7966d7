/**
 * The "mistake switches": each one puts back a mistake found in a real student's
 * program. All are off by default. Render and Stages read the same switches.
 */
public class Switches {
    /** How the screen coordinates are made whole. */
    public enum Rounding { CAST, NONE, FLOOR, CEIL }

    /** When N is normalised in Gram-Schmidt. */
    public enum NNormalisation { FIRST, NEVER, AFTER }

    public Rounding rounding = Rounding.CAST;                 // --no-int-cast, --floor-screen, --ceil-screen
    public boolean specularWithoutNlTest = false;            // --specular-without-nl-test
    public boolean edgesYaxb = false;                        // --edges-y-ax-b
    public boolean scanIndexBug = false;                     // --scan-index-bug
    public boolean gramSchmidtFloat = false;                 // --gram-schmidt-float
    public boolean lightInPlace = false;                     // --light-in-place
    public NNormalisation nNormalisation = NNormalisation.FIRST; // --n-not-normalised=never|after
    public boolean vertexNormalsFrontOnly = false;           // --vertex-normals-front-only

    public static final String HELP =
        "mistake switches (all off by default):\n"
        + "  --no-int-cast                screen coordinates left as doubles (never cast to int)\n"
        + "  --floor-screen               screen coordinates made whole with Math.floor\n"
        + "  --ceil-screen                screen coordinates made whole with Math.ceil\n"
        + "  --specular-without-nl-test   specular added where R.V > 0 even when N.L < 0\n"
        + "  --edges-y-ax-b               scan edges as y = a*x + b, crossing x = (y - b)/a\n"
        + "  --scan-index-bug             per-row scan table indexed without bounds check (crashes)\n"
        + "  --gram-schmidt-float         camera basis computed with float variables\n"
        + "  --light-in-place             light moved to view coordinates in place (aliasing)\n"
        + "  --n-not-normalised=never     N never normalised in Gram-Schmidt\n"
        + "  --n-not-normalised=after     N normalised only after V - (V.N)N\n"
        + "  --vertex-normals-front-only  vertex normals summed only from front-facing triangles\n";

    /**
     * Tries to read one switch. Returns true when arg was a mistake switch.
     * The three screen-rounding switches set the same thing: the last one given wins.
     */
    public boolean parse(String arg) {
        switch (arg) {
            case "--no-int-cast": rounding = Rounding.NONE; return true;
            case "--floor-screen": rounding = Rounding.FLOOR; return true;
            case "--ceil-screen": rounding = Rounding.CEIL; return true;
            case "--specular-without-nl-test": specularWithoutNlTest = true; return true;
            case "--edges-y-ax-b": edgesYaxb = true; return true;
            case "--scan-index-bug": scanIndexBug = true; return true;
            case "--gram-schmidt-float": gramSchmidtFloat = true; return true;
            case "--light-in-place": lightInPlace = true; return true;
            case "--n-not-normalised=never": nNormalisation = NNormalisation.NEVER; return true;
            case "--n-not-normalised=after": nNormalisation = NNormalisation.AFTER; return true;
            case "--vertex-normals-front-only": vertexNormalsFrontOnly = true; return true;
            default: return false;
        }
    }

    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder();
        if (rounding == Rounding.NONE) sb.append(" --no-int-cast");
        if (rounding == Rounding.FLOOR) sb.append(" --floor-screen");
        if (rounding == Rounding.CEIL) sb.append(" --ceil-screen");
        if (specularWithoutNlTest) sb.append(" --specular-without-nl-test");
        if (edgesYaxb) sb.append(" --edges-y-ax-b");
        if (scanIndexBug) sb.append(" --scan-index-bug");
        if (gramSchmidtFloat) sb.append(" --gram-schmidt-float");
        if (lightInPlace) sb.append(" --light-in-place");
        if (nNormalisation == NNormalisation.NEVER) sb.append(" --n-not-normalised=never");
        if (nNormalisation == NNormalisation.AFTER) sb.append(" --n-not-normalised=after");
        if (vertexNormalsFrontOnly) sb.append(" --vertex-normals-front-only");
        return sb.length() == 0 ? "(none)" : sb.toString().trim();
    }
}
