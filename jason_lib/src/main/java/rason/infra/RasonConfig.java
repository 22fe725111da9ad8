package rason.infra;

import jason.util.Config;

/**
 * Jason's configuration, with Rason's web mind inspector in place of Jason's: the
 * {@code .mas2j} option {@code mindinspector="web(...)"} then serves on loopback, on a
 * free port of its own ({@link LoopbackMindInspector}). Put in place by
 * {@link RasonLocalMAS} through Jason's own {@code Config.setClassFactory}.
 */
public class RasonConfig extends Config {

    @Override
    public String getMindInspectorWebServerClassName() {
        return LoopbackMindInspector.class.getName();
    }
}
