package rason.core;

import java.util.ArrayDeque;
import java.util.Deque;

import jason.asSyntax.ListTerm;
import jason.asSyntax.Literal;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;

/**
 * Bounds on text that arrives from the network, so that one perception or
 * message cannot stop an agent: long text makes Jason's parser slow (a long
 * token costs time quadratic in its length), deep nesting overflows the stack
 * of the parser or, later, of the agent's thread. The text checks are one
 * linear scan without recursion, made before Jason's parser runs; the term
 * check walks the parsed term with an explicit stack.
 * <p>
 * The bridge makes one instance and hands it to what parses input; the node sets
 * it from its ~params. Setters refuse values below 1.
 */
public final class InputLimits {

    public static final int DEFAULT_MAX_LITERAL_LENGTH = 4096;
    public static final int DEFAULT_MAX_NESTING = 32;
    public static final int DEFAULT_MAX_TERM_DEPTH = 512;
    public static final int DEFAULT_MAX_LITERALS = 1000;
    public static final int DEFAULT_MAX_CONTENT_LENGTH = 64 * 1024;
    public static final int DEFAULT_MAX_SOURCES = 100;
    /** Characters of a perception source's name: every per-source table holds the names. */
    public static final int MAX_SOURCE_LENGTH = 256;

    private volatile int maxLiteralLength = DEFAULT_MAX_LITERAL_LENGTH;
    private volatile int maxNesting = DEFAULT_MAX_NESTING;
    private volatile int maxTermDepth = DEFAULT_MAX_TERM_DEPTH;
    private volatile int maxLiterals = DEFAULT_MAX_LITERALS;
    private volatile int maxContentLength = DEFAULT_MAX_CONTENT_LENGTH;
    private volatile int maxSources = DEFAULT_MAX_SOURCES;

    public int maxLiteralLength() {
        return maxLiteralLength;
    }

    /** Characters of one perception literal (or action result read as a literal). */
    public InputLimits setMaxLiteralLength(int n) {
        maxLiteralLength = positive("max_literal_length", n);
        return this;
    }

    public int maxNesting() {
        return maxNesting;
    }

    /** Brackets ( [ { open at once in the text, outside quotes and comments. */
    public InputLimits setMaxNesting(int n) {
        maxNesting = positive("max_nesting", n);
        return this;
    }

    public int maxTermDepth() {
        return maxTermDepth;
    }

    /**
     * Depth of the parsed term, where each argument, annotation, list element
     * and operand of an operator is one level deeper: Jason walks lists and
     * expressions recursively, so a long list or a+a+a+… is as deep as its length.
     */
    public InputLimits setMaxTermDepth(int n) {
        maxTermDepth = positive("max_term_depth", n);
        return this;
    }

    public int maxLiterals() {
        return maxLiterals;
    }

    /** Literals in one perception message; a message with more is dropped whole. */
    public InputLimits setMaxLiterals(int n) {
        maxLiterals = positive("max_literals", n);
        return this;
    }

    public int maxContentLength() {
        return maxContentLength;
    }

    /** Characters of one agent message's content. */
    public InputLimits setMaxContentLength(int n) {
        maxContentLength = positive("max_content_length", n);
        return this;
    }

    public int maxSources() {
        return maxSources;
    }

    /**
     * Perception sources remembered at once (heard within the perception TTL and not
     * cleared); a message from a new source beyond them is dropped, so a flood of
     * distinct source names cannot grow the per-source tables without bound.
     */
    public InputLimits setMaxSources(int n) {
        maxSources = positive("max_sources", n);
        return this;
    }

    private static int positive(String name, int n) {
        if (n < 1)
            throw new IllegalArgumentException(name + " must be 1 or more, not " + n);
        return n;
    }

    /**
     * Checks text before it is parsed: its length, then the nesting of ( [ {
     * outside "strings", 'quoted atoms' and comments (as Jason's lexer reads
     * them), then an estimate of the term's depth from above: each open bracket,
     * each , or | inside [ ] and each operator character (+ - * / &lt; &gt; = &amp; | ~ \ ^ :)
     * counts one level until its bracket closes, since Jason's parser, too,
     * recurses once per list element and operator.
     *
     * @return null if it may be parsed, else why not ("longer than 4096 characters", "nesting deeper than 32",
     *         "term deeper than 512 levels …")
     */
    public static String checkText(String text, int maxLength, int maxNesting, int maxTermDepth) {
        int n = text.length();
        if (n > maxLength)
            return "longer than " + maxLength + " characters";
        int depth = 0;
        long estimate = 1; // the term's depth as the text shows it, from above
        long[] chain = new long[maxNesting + 1]; // what each open bracket level added to the estimate
        boolean[] list = new boolean[maxNesting + 1]; // whether that level is a [ ]
        for (int i = 0; i < n; i++) {
            char c = text.charAt(i);
            switch (c) {
            case '"', '\'' -> { // to the closing quote; a backslash escapes the next character
                int j = i + 1;
                while (j < n && text.charAt(j) != c)
                    j += text.charAt(j) == '\\' ? 2 : 1;
                i = j;
            }
            case '/' -> {
                if (i + 1 < n && text.charAt(i + 1) == '*') {
                    int end = text.indexOf("*/", i + 2);
                    i = end < 0 ? n : end + 1;
                } else if (i + 1 < n && text.charAt(i + 1) == '/') {
                    int end = text.indexOf('\n', i + 2);
                    i = end < 0 ? n : end;
                } else { // division
                    chain[depth]++;
                    estimate++;
                }
            }
            case '(', '[', '{' -> {
                if (++depth > maxNesting)
                    return "nesting deeper than " + maxNesting;
                chain[depth] = 1;
                list[depth] = c == '[';
                estimate++;
            }
            case ')', ']', '}' -> {
                if (depth > 0) {
                    estimate -= chain[depth];
                    depth--;
                }
            }
            case ',' -> {
                if (list[depth]) {
                    chain[depth]++;
                    estimate++;
                }
            }
            case '+', '-', '*', '<', '>', '=', '&', '|', '~', '\\', '^', ':' -> {
                chain[depth]++;
                estimate++;
            }
            default -> {
            }
            }
            if (estimate > maxTermDepth)
                return tooDeep(maxTermDepth);
        }
        return null;
    }

    private static String tooDeep(int maxTermDepth) {
        return "term deeper than " + maxTermDepth + " levels (each list element and operator counts one)";
    }

    /**
     * Checks a parsed term's depth (see {@link #setMaxTermDepth}) without recursion.
     *
     * @return null if it is within maxDepth, else why not
     */
    public static String checkDepth(Term term, int maxDepth) {
        Deque<Term> terms = new ArrayDeque<>();
        Deque<Integer> depths = new ArrayDeque<>();
        terms.push(term);
        depths.push(1);
        while (!terms.isEmpty()) {
            Term t = terms.pop();
            int d = depths.pop();
            if (d > maxDepth)
                return tooDeep(maxDepth);
            if (t instanceof ListTerm l) {
                if (!l.isEmpty() && !t.isVar()) {
                    push(terms, depths, l.getTerm(), d + 1);
                    push(terms, depths, l.getNext(), d + 1);
                }
            } else if (t instanceof Structure s && !t.isVar()) {
                for (int i = 0; i < s.getArity(); i++)
                    push(terms, depths, s.getTerm(i), d + 1);
                if (t instanceof Literal lit && lit.hasAnnot())
                    push(terms, depths, lit.getAnnots(), d + 1);
            }
        }
        return null;
    }

    private static void push(Deque<Term> terms, Deque<Integer> depths, Term t, int depth) {
        if (t != null) {
            terms.push(t);
            depths.push(depth);
        }
    }

    /** text as a log line shows it: at most max characters, and how long it was if cut. */
    public static String abbreviate(String text, int max) {
        if (text == null || text.length() <= max)
            return text;
        return text.substring(0, max) + "… (" + text.length() + " characters)";
    }
}
