package phalanx.motion;

import java.nio.file.Path;

/**
 * A motion file that cannot be used, with the file, the line (0 when unknown), the phase or pose,
 * and the field at fault, so the message alone says what to fix.
 */
public final class MotionFileException extends Exception {
    private final String file;
    private final int line;
    private final String part;
    private final String field;

    public MotionFileException(Path file, int line, String part, String field, String problem) {
        this(file == null ? "<unnamed>" : file.toString(), line, part, field, problem, null);
    }

    public MotionFileException(String file, int line, String part, String field, String problem, Throwable cause) {
        super(format(file, line, part, field, problem), cause);
        this.file = file;
        this.line = line;
        this.part = part;
        this.field = field;
    }

    /** The file as given to the loader. */
    public String file() { return file; }
    /** 1-based line, 0 when the problem is not tied to one line. */
    public int line() { return line; }
    /** "phase 'Step1'", "pose 'Pose3'", or null for the whole file. */
    public String part() { return part; }
    /** The field at fault ("next", "duration", "effectors/llj9", "header"...), or null. */
    public String field() { return field; }

    private static String format(String file, int line, String part, String field, String problem) {
        StringBuilder sb = new StringBuilder(file);
        if (line > 0) sb.append(':').append(line);
        sb.append(": ");
        if (part != null) sb.append(part).append(", ");
        if (field != null) sb.append("field '").append(field).append("': ");
        return sb.append(problem).toString();
    }
}
