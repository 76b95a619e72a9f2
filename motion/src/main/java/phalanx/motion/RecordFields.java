package phalanx.motion;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.RecordComponent;
import java.util.Arrays;

/** A config record's copy with one named number changed: the benches' {@code --set FIELD=VALUE}. */
public final class RecordFields {
    private RecordFields() { }

    /**
     * {@code r} with its component {@code name} (a double) set to {@code value}, through the canonical constructor, so
     * the record's own checks apply and their IllegalArgumentException comes through as it is. An unknown name, or one
     * that is not a double, throws IllegalArgumentException naming the record and its fields.
     */
    @SuppressWarnings("unchecked")
    public static <R extends Record> R withDouble(R r, String name, double value) {
        Class<?> type = r.getClass();
        RecordComponent[] rc = type.getRecordComponents();
        Object[] args = new Object[rc.length];
        Class<?>[] types = new Class<?>[rc.length];
        boolean found = false;
        try {
            for (int i = 0; i < rc.length; i++) {
                types[i] = rc[i].getType();
                boolean it = rc[i].getName().equals(name) && types[i] == double.class;
                args[i] = it ? (Object) value : rc[i].getAccessor().invoke(r);
                found |= it;
            }
            if (!found) {
                String fields = String.join(", ", Arrays.stream(rc).filter(c -> c.getType() == double.class).map(RecordComponent::getName).toList());
                throw new IllegalArgumentException("no " + type.getName().substring(type.getName().lastIndexOf('.') + 1).replace('$', '.')
                        + " field " + name + " (" + fields + ")");
            }
            Constructor<?> c = type.getDeclaredConstructor(types);
            return (R) c.newInstance(args);
        } catch (InvocationTargetException e) {
            if (e.getCause() instanceof RuntimeException re) throw re;
            throw new IllegalStateException(e.getCause());
        } catch (ReflectiveOperationException e) {
            throw new IllegalStateException(e);
        }
    }
}
