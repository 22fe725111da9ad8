package rason.messaging;

import java.util.Map;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Supplier;

import jason.asSemantics.Message;
import jason.asSyntax.ASSyntax;
import jason.asSyntax.Atom;
import jason.asSyntax.Literal;
import jason.asSyntax.StringTermImpl;
import jason.infra.local.LocalAgArch;

/**
 * Jason's directory facilitator ({@code .df_register}, {@code .df_search},
 * {@code .df_subscribe}) over the whole fleet: our agents' registrations are announced with
 * our presence, at once when they change; subscribers hear of providers that come and go as
 * from Jason's own DF.
 */
public final class DirectoryFacilitator {

    /** Jason's name for the directory facilitator: subscribers hear from it, as in one MAS. */
    public static final String DF_NAME = "df";

    private final FleetDirectory directory;
    private final Supplier<Map<String, LocalAgArch>> jasonAgents;
    private final Supplier<FleetChannel> channel;
    private final AtomicBoolean announceQueued = new AtomicBoolean();

    DirectoryFacilitator(FleetDirectory directory, Supplier<Map<String, LocalAgArch>> jasonAgents,
            Supplier<FleetChannel> channel) {
        this.directory = directory;
        this.jasonAgents = jasonAgents;
        this.channel = channel;
    }

    public FleetDirectory directory() {
        return directory;
    }

    public void register(String agent, String service) {
        if (directory.register(agent, service))
            announceSoon();
    }

    public void deregister(String agent, String service) {
        if (directory.deregister(agent, service))
            announceSoon();
    }

    /** A hosted agent stopped: its registrations and subscriptions go. */
    public void agentGone(String agent) {
        if (directory.agentGone(agent))
            announceSoon();
    }

    /** Our registrations, for the presence about to be announced (a later change queues another). */
    FleetDirectory.Announced announced() {
        announceQueued.set(false);
        return directory.announced();
    }

    /**
     * Other processes hear of a change of our agents or their registrations at once, not at our
     * next periodic announcement (one announcement for changes queued before it goes out).
     */
    void announceSoon() {
        if (announceQueued.compareAndSet(false, true) && !channel.get().announceNow())
            announceQueued.set(false); // no channel yet: its first announcement will have them
    }

    /** A node takes the channel again: an earlier node's queued announcement went with it. */
    void reopen() {
        announceQueued.set(false);
    }

    /**
     * Tells subscribers what the directory says changed, as Jason's DF does: tell
     * provider(Agent, "service") from df when one comes, untell when one goes. Only queues
     * the messages in their mailboxes: each agent takes them on its own thread.
     */
    void providersChanged(java.util.List<FleetDirectory.Notice> notices) {
        Map<String, LocalAgArch> hosted = jasonAgents.get();
        for (FleetDirectory.Notice n : notices) {
            LocalAgArch la = hosted.get(n.subscriber());
            if (la == null)
                continue;
            Literal provider = ASSyntax.createLiteral("provider", new Atom(n.provider()), new StringTermImpl(n.service()));
            la.receiveMsg(new Message(n.added() ? "tell" : "untell", DF_NAME, n.subscriber(), provider));
        }
    }
}
