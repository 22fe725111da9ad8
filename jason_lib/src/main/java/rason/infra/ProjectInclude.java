package rason.infra;

import java.io.File;
import java.io.IOException;
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

/**
 * Jason's {@code include} directive (and so {@code .include}), finding a
 * relative file the way a project means it whatever the working directory:
 * next to the including file, then in the .mas2j's directory, then in each of
 * its {@code aslSourcePath} directories (relative ones taken from the .mas2j's
 * directory). Jason 3.2 looks in the including file's directory only when the
 * working directory is the root (it drops the leading '/' of that path), and
 * takes relative source paths from the working directory, which under
 * roslaunch is ROS_HOME. A file found nowhere is reported with every path
 * tried; URLs and Jason's {@code $jar/...} paths are left to Jason.
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
        if (isUrl(name) || name.startsWith("$"))
            return super.process(directive, outerContent, innerContent);
        List<File> tried = candidates(name, includingSource(directive, outerContent));
        File found = null;
        for (File f : tried)
            if (f.isFile()) {
                found = f;
                break;
            }
        if (found == null) {
            String line = "agent '" + agentName(outerContent) + "': included file '" + name + "' not found; tried "
                    + tried;
            if (loading)
                synchronized (failures) {
                    failures.add(line);
                }
            logger.log(Level.SEVERE, line);
            return null;
        }
        // Jason reads the file; the namespace it picks for a variable (include(F, NS)) goes back to the caller
        Pred resolved = (Pred) directive.copy();
        resolved.setTerm(0, new StringTermImpl(found.getPath()));
        Agent result = super.process(resolved, outerContent, innerContent);
        if (directive.getArity() > 1)
            directive.setTerm(1, resolved.getTerm(1));
        return result;
    }

    /**
     * Where a relative name is looked for, in order (without duplicates): the
     * including file's directory, the project's directory, its source paths.
     */
    List<File> candidates(String name, String includingSource) {
        File given = new File(name);
        if (given.isAbsolute())
            return List.of(canonical(given));
        Set<File> dirs = new LinkedHashSet<>();
        File including = localFile(includingSource);
        if (including != null && including.getParentFile() != null)
            dirs.add(canonical(including.getParentFile()));
        File project = projectDir;
        if (project != null)
            dirs.add(canonical(project));
        for (String p : sourcePaths) {
            File dir = localFile(p);
            if (dir != null)
                dirs.add(canonical(dir));
        }
        List<File> out = new ArrayList<>();
        for (File d : dirs)
            out.add(canonical(new File(d, name)));
        return out;
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

    /** A path or file: URL as a file, relative ones taken from the project's directory; null for other URLs. */
    private File localFile(String source) {
        if (source == null || source.isEmpty())
            return null;
        String s = source.startsWith("\"") && source.endsWith("\"") && source.length() > 1
                ? source.substring(1, source.length() - 1)
                : source;
        if (s.startsWith("file:"))
            s = s.substring("file:".length());
        else if (isUrl(s))
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
