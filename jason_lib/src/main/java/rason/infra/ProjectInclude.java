package rason.infra;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.logging.Level;
import java.util.logging.Logger;

import jason.asSemantics.Agent;
import jason.asSyntax.Pred;
import jason.asSyntax.StringTerm;
import jason.asSyntax.StringTermImpl;
import jason.asSyntax.Term;
import jason.asSyntax.directives.Include;
import jason.util.Config;

/**
 * Jason's {@code include} directive (and so {@code .include}), finding a
 * relative file the way a project means it whatever the working directory:
 * next to the including file, then in the .mas2j's directory, then in each of
 * its {@code aslSourcePath} directories (relative ones taken from the .mas2j's
 * directory; {@code $jasonJar/...} ones inside Jason's jar). Jason 3.2 looks in
 * the including file's directory only when the working directory is the root
 * (it drops the leading '/' of that path), and takes relative source paths from
 * the working directory, which under roslaunch is ROS_HOME. Jason's
 * {@code $jasonJar/...} paths are resolved as Jason resolves them. A file found
 * that the working directory names the same keeps its name as written (as Jason
 * shows it, run in the project's folder); others get their full path. A file found
 * nowhere is reported with every path tried; URLs are left to Jason.
 */
public class ProjectInclude extends Include {

    private static final Logger logger = Logger.getLogger(ProjectInclude.class.getName());

    private volatile File projectDir = null;
    private volatile List<String> sourcePaths = List.of();
    private final List<String> failures = new ArrayList<>(); // guarded by itself
    private volatile boolean loading = false; // failures are kept while the project's agents are made

    /** The project's directory and its aslSourcePath entries (as the .mas2j writes them). */
    public void setProject(File directory, List<String> paths) {
        projectDir = directory;
        sourcePaths = List.copyOf(paths);
        synchronized (failures) {
            failures.clear();
        }
        loading = true;
    }

    /** The project's agents are made: later failures (of .include) are only logged. */
    public void loaded() {
        loading = false;
        synchronized (failures) {
            failures.clear();
        }
    }

    @Override
    public Agent process(Pred directive, Agent outerContent, Agent innerContent) {
        if (outerContent == null || directive.getArity() < 1 || !directive.getTerm(0).isString())
            return super.process(directive, outerContent, innerContent);
        String name = ((StringTerm) directive.getTerm(0)).getString().replace('\\', '/');
        if (isUrl(name))
            return super.process(directive, outerContent, innerContent);
        Resolution r = resolve(name, includingSource(directive, outerContent));
        if (r.found() == null) {
            String line = "agent '" + agentName(outerContent) + "': included file '" + name + "' not found; tried "
                    + r.tried() + unconfigured(name);
            if (loading)
                synchronized (failures) {
                    failures.add(line);
                }
            logger.log(Level.SEVERE, line);
            return null;
        }
        // Jason reads the file; the namespace it picks for a variable (include(F, NS)) goes back to the caller
        Pred resolved = (Pred) directive.copy();
        resolved.setTerm(0, new StringTermImpl(r.found()));
        Agent result = super.process(resolved, outerContent, innerContent);
        if (directive.getArity() > 1)
            directive.setTerm(1, resolved.getTerm(1));
        return result;
    }

    /** Where a name was found (a file's path or a URL Jason reads; null if nowhere), and every place tried. */
    record Resolution(String found, List<String> tried) {
    }

    /**
     * Finds a source as an include does: a {@code $jasonJar/...} name in Jason's jar;
     * an absolute path or a URL as it is; a relative name in the including file's
     * directory (a file's or a jar's), the project's directory, its source paths.
     */
    Resolution resolve(String name, String includingSource) {
        List<String> tried = new ArrayList<>();
        if (name.startsWith("$")) { // $jasonJar/x: x inside the jar Jason's configuration names so
            int slash = name.indexOf('/');
            File jar = slash < 0 ? null : Config.get().getPackage(name.substring(1, slash));
            String url = jar == null ? name : "jar:file:" + jar.getAbsolutePath() + "!" + name.substring(slash);
            tried.add(url);
            return new Resolution(jar != null && readable(url) ? url : null, tried);
        }
        if (isUrl(name) || new File(name).isAbsolute()) {
            String given = isUrl(name) ? name : canonical(new File(name)).getPath();
            tried.add(given);
            return new Resolution(readable(given) ? given : null, tried);
        }
        for (String dir : directories(includingSource)) {
            String candidate = isUrl(dir) ? dir + "/" + name : canonical(new File(dir, name)).getPath();
            if (!tried.contains(candidate))
                tried.add(candidate);
            if (readable(candidate))
                return new Resolution(isUrl(candidate) ? candidate : asWritten(name, candidate), tried);
        }
        return new Resolution(null, tried);
    }

    /**
     * The name as the program wrote it if, taken from the working directory, it is the
     * file found: Jason reads the same file, and shows its name (code_src, url(...)) as
     * Jason's runner run in the project's folder does. Otherwise the path found.
     */
    private static String asWritten(String name, String found) {
        return canonical(new File(name)).getPath().equals(found) ? name : found;
    }

    /** The directories (paths, or URLs inside a jar) a relative name is looked for in, in order. */
    private List<String> directories(String includingSource) {
        Set<String> dirs = new LinkedHashSet<>();
        if (includingSource != null && isJarUrl(includingSource))
            dirs.add(includingSource.substring(0, includingSource.lastIndexOf('/')));
        File including = includingFile(includingSource);
        if (including != null && including.getParentFile() != null)
            dirs.add(canonical(including.getParentFile()).getPath());
        File project = projectDir;
        if (project != null)
            dirs.add(canonical(project).getPath());
        for (String p : sourcePaths) {
            String unquoted = unquote(p);
            if (isJarUrl(unquoted)) {
                dirs.add(unquoted.endsWith("/") ? unquoted.substring(0, unquoted.length() - 1) : unquoted);
                continue;
            }
            File dir = localFile(p);
            if (dir != null)
                dirs.add(canonical(dir).getPath());
        }
        return new ArrayList<>(dirs);
    }

    /** Why a {@code $name/...} path cannot be found: its name is not in Jason's configuration. */
    private static String unconfigured(String name) {
        int slash = name.indexOf('/');
        if (!name.startsWith("$") || slash < 0)
            return "";
        String key = name.substring(1, slash);
        return Config.get().getPackage(key) == null ? " ($" + key + " is not in Jason's configuration)" : "";
    }

    private static boolean readable(String location) {
        if (!isUrl(location))
            return new File(location).isFile();
        if (location.startsWith("file:"))
            return new File(location.substring("file:".length())).isFile();
        if (!isJarUrl(location))
            return false; // nothing is fetched from the network to find a file
        try (InputStream in = new URL(location).openStream()) {
            return true;
        } catch (IOException | RuntimeException e) {
            return false;
        }
    }

    private static boolean isJarUrl(String s) {
        return s.startsWith("jar:") && s.contains("!/");
    }

    private static String unquote(String s) {
        return s.startsWith("\"") && s.endsWith("\"") && s.length() > 1 ? s.substring(1, s.length() - 1) : s;
    }

    /**
     * The file the directive is in: the agent's source once it is loaded (.include, nested includes),
     * else the file the parser is reading (Jason sets the agent's source only after parsing it).
     */
    private static String includingSource(Pred directive, Agent outer) {
        if (outer.getASLSrc() != null && !outer.getASLSrc().isEmpty())
            return outer.getASLSrc();
        for (Term t : new Term[] { directive, directive.getTerm(0) })
            if (t.getSrcInfo() != null && t.getSrcInfo().getSrcFile() != null)
                return t.getSrcInfo().getSrcFile();
        return null;
    }

    /** The includes not found while the project's agents were made (one line each). */
    public List<String> failures() {
        synchronized (failures) {
            return new ArrayList<>(failures);
        }
    }

    /**
     * The file a directive or .create_agent is in, as Jason read it: a relative name is
     * one kept as written ({@link #asWritten}), from the working directory; null for a URL.
     */
    private static File includingFile(String source) {
        String s = localPath(source);
        return s == null ? null : new File(s).getAbsoluteFile();
    }

    /** A path, or a file: URL's path, as written; null for nothing or another URL. */
    private static String localPath(String source) {
        if (source == null || source.isEmpty())
            return null;
        String s = unquote(source);
        if (s.startsWith("file:"))
            return s.substring("file:".length());
        return isUrl(s) ? null : s;
    }

    /** A path or file: URL as a file, relative ones taken from the project's directory; null for other URLs. */
    private File localFile(String source) {
        String s = localPath(source);
        if (s == null)
            return null;
        File f = new File(s);
        if (!f.isAbsolute() && projectDir != null)
            f = new File(projectDir, s);
        return f;
    }

    /** jar:, http:, ClassResource: ... (a Windows drive letter is not a scheme). */
    private static boolean isUrl(String s) {
        int colon = s.indexOf(':');
        return colon > 1 && s.substring(0, colon).matches("[A-Za-z][A-Za-z0-9+.-]*");
    }

    private static File canonical(File f) {
        try {
            return f.getCanonicalFile();
        } catch (IOException e) {
            return f.getAbsoluteFile();
        }
    }

    private static String agentName(Agent ag) {
        try {
            return ag.getTS().getAgArch().getAgName();
        } catch (RuntimeException e) {
            return String.valueOf(ag.getASLSrc());
        }
    }
}
