package rason.perception;

/**
 * A perception manager that is not part of Rason, as a user would name it in
 * the .mas2j (public, with a public constructor without arguments).
 */
public class PluginPerception extends PerSourcePerception {

    @Override
    public String toString() {
        return "plugin";
    }
}
