package rason.messaging;

import java.security.SecureRandom;
import java.util.regex.Pattern;

import jason.asSemantics.Message;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.ListTerm;
import jason.asSyntax.ListTermImpl;
import jason.asSyntax.Plan;
import jason.asSyntax.Pred;
import jason.asSyntax.StringTerm;
import jason.asSyntax.StringTermImpl;
import jason.asSyntax.Structure;
import jason.asSyntax.Term;

import rason.core.InputLimits;
import rason.core.JasonParser;

/** Jason messages as they cross between processes: content as Jason text, parsed once on arrival. */
public final class Messages {

    private Messages() {
    }

    /** The content of m as Jason text (what the receiver parses back). */
    public static String contentText(Message m) {
        Object c = m.getPropCont();
        if (c instanceof Term t)
            return escapeStrings(t).toString();
        return c == null ? "" : c.toString();
    }

    /**
     * A copy of t whose strings print with escapes: Jason prints a string's
     * value between quotes as it is, so "say \"hi\"" would not parse back.
     */
    static Term escapeStrings(Term t) {
        if (t instanceof Plan p) // a plan (an askHow's answer) prints its own text, and Jason cannot set its terms
            return withProcessLabel(p);
        if (t.isString()) {
            String v = ((StringTerm) t).getString();
            String e = escape(v);
            return e.equals(v) ? t : new StringTermImpl(e);
        }
        if (t instanceof ListTermImpl) {
            ListTerm copy = ((ListTerm) t).cloneLT();
            for (Term node = copy; node instanceof ListTermImpl l && !l.isEmpty(); node = l.getNext())
                l.setTerm(escapeStrings(l.getTerm()));
            return copy;
        }
        if (t instanceof Structure s && !t.isVar() && (s.getArity() > 0 || s instanceof Pred p && p.hasAnnot())) {
            Structure copy = (Structure) s.clone();
            for (int i = 0; i < copy.getArity(); i++)
                copy.setTerm(i, escapeStrings(copy.getTerm(i)));
            if (copy instanceof Pred p && p.hasAnnot())
                p.setAnnots((ListTerm) escapeStrings(p.getAnnots()));
            return copy;
        }
        return t;
    }

    /** Jason's label for a plan written without one: p__ and a counter of the process. */
    private static final Pattern GENERATED_LABEL = Pattern.compile("p__\\d+");
    /** Tags this process's generated labels when they leave it (letters and digits, as an atom allows). */
    static final String PROCESS_TAG = Long.toString(new SecureRandom().nextLong() & Long.MAX_VALUE, 36);

    /**
     * Jason labels plans written without a label p__1, p__2, ... with one counter per
     * process, so in one MAS no two plans share a generated label; another process has
     * its own p__3, and adding a plan under a label the agent already has fails. A
     * generated label leaves with this process's tag (p__3_k2x9...), so it stays unique
     * in the receiver as it would in one MAS; its annotations (source, url) are kept.
     */
    static Plan withProcessLabel(Plan p) {
        Pred label = p.getLabel();
        if (label == null || !GENERATED_LABEL.matcher(label.getFunctor()).matches())
            return p;
        Plan copy = (Plan) p.clone();
        Pred tagged = new Pred(label.getFunctor() + "_" + PROCESS_TAG);
        if (label.hasAnnot())
            tagged.setAnnots(label.getAnnots().cloneLT());
        copy.setLabel(tagged);
        return copy;
    }

    // Jason's parser turns \" and \n back into a quote and a newline and keeps
    // any other backslash sequence as it is, so only these two are escaped.
    private static String escape(String v) {
        if (v == null)
            return "";
        StringBuilder b = new StringBuilder(v.length());
        for (char ch : v.toCharArray()) {
            switch (ch) {
            case '"' -> b.append("\\\"");
            case '\n' -> b.append("\\n");
            default -> b.append(ch);
            }
        }
        return b.toString();
    }

    /**
     * Parses received content within the default limits (a fresh {@link InputLimits}).
     *
     * @throws IllegalArgumentException saying why it is not a Jason term
     */
    public static Term parseContent(String text) {
        return parseContent(text, new InputLimits());
    }

    /**
     * Parses received content; content longer or more deeply nested than the
     * limits is refused before Jason's parser sees it.
     *
     * @throws IllegalArgumentException saying why it is not a Jason term or is refused
     */
    public static Term parseContent(String text, InputLimits limits) {
        if (text == null || text.isBlank())
            throw new IllegalArgumentException("empty content");
        String shown = InputLimits.abbreviate(text, 200);
        String tooBig = InputLimits.checkText(text, limits.maxContentLength(), limits.maxNesting(), limits.maxTermDepth());
        if (tooBig != null)
            throw new IllegalArgumentException("content '" + shown + "' refused: " + tooBig);
        Term term;
        try {
            term = JasonParser.term(text.strip());
        } catch (Exception | Error e) { // ParseException, or TokenMgrError from the lexer
            String why = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
            int nl = why.indexOf('\n');
            throw new IllegalArgumentException("content '" + shown + "' is not a Jason term: " + (nl < 0 ? why : why.substring(0, nl)));
        }
        String tooDeep = InputLimits.checkDepth(term, limits.maxTermDepth());
        if (tooDeep != null)
            throw new IllegalArgumentException("content '" + shown + "' refused: " + tooDeep);
        return term;
    }

    /** The message the receiving agent's mailbox gets; an empty id gets a fresh one from this JVM. */
    public static Message toJason(String performative, String sender, String receiver, Term content, String msgId,
            String inReplyTo) {
        Message m = msgId == null || msgId.isEmpty()
                ? new Message(performative, sender, receiver, content)
                : new Message(performative, sender, receiver, content, msgId);
        if (inReplyTo != null && !inReplyTo.isEmpty())
            m.setInReplyTo(inReplyTo);
        return m;
    }
}
