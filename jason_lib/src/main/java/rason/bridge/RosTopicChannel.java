package rason.bridge;

import rason.messaging.FleetAuth;
import rason.messaging.FleetChannel;
import rason.messaging.FleetDirectory;
import rason.messaging.FleetPort;
import rason.messaging.WireMessage;

/**
 * The fleet over ROS topics of one master (/rason/messages, /rason/presence, /rason/pulse): what the
 * agents send is queued in the {@link Outbox} for the node, which signs it here in
 * publishing order and publishes it; what the node's subscribers receive comes in here.
 */
public final class RosTopicChannel implements FleetChannel {

    private final Outbox outbox;
    private FleetPort port; // set once by the composition root, before any agent runs

    RosTopicChannel(Outbox outbox) {
        this.outbox = outbox;
    }

    void connect(FleetPort fleet) {
        this.port = fleet;
    }

    @Override
    public boolean send(WireMessage m) {
        return outbox.offer(new Outbound.AgentMessage(m.receiverMas(), m.sender(), m.receiver(), m.performative(),
                m.content(), m.msgId(), m.inReplyTo()));
    }

    @Override
    public boolean announceNow() {
        return outbox.offer(new Outbound.Announce());
    }

    /**
     * The authentication fields of an agent message of ours the node is about to publish (the
     * fields of an {@link Outbound.AgentMessage}); sign in publishing order, so that the sequence
     * numbers arrive increasing.
     */
    public FleetAuth.Signed sign(String receiverMas, String sender, String receiver, String performative,
            String content, String msgId, String inReplyTo) {
        return port.sign(new WireMessage(port.masId(), sender, receiverMas, receiver, performative, content, msgId,
                inReplyTo));
    }

    /** Our registrations, for the presence the node is about to announce. */
    public FleetDirectory.Announced announced() {
        return port.announced();
    }

    /** The authentication fields of the presence the node is about to announce. */
    public FleetAuth.Signed signPresence(String[] agents, String[] dfAgents, String[] dfServices, float period,
            boolean leaving) {
        return port.signPresence(agents, dfAgents, dfServices, period, leaving, "");
    }

    /** The authentication fields of the pulse the node is about to publish. */
    public FleetAuth.Signed signPulse() {
        return port.auth().signPulse(port.masId());
    }

    /** A rason_msgs/Pulse arrived: its fields as published, the uint64 ones as their bits. */
    public void pulseArrived(String mas, long incarnation, long sequence, long stamp, String keyId, byte[] mac,
            String publisher) {
        port.fleet().pulseArrived(mas, new FleetAuth.Signed(incarnation, sequence, stamp, keyId, mac), publisher);
    }

    /**
     * A rason_msgs/AgentMessage arrived: its fields as published, the uint64 ones as their bits.
     *
     * @param publisher the node that published it (from the connection; "" if unknown)
     * @return how many hosted agents it was delivered to
     */
    public int deliver(String senderMas, String sender, String receiverMas, String receiver, String performative,
            String content, String msgId, String inReplyTo, long incarnation, long sequence, long stamp, String keyId,
            byte[] mac, String publisher) {
        return port.deliver(new WireMessage(senderMas, sender, receiverMas, receiver, performative, content, msgId,
                inReplyTo), new FleetAuth.Signed(incarnation, sequence, stamp, keyId, mac), publisher);
    }

    /** A rason_msgs/Presence arrived: its fields as published, the uint64 ones as their bits. */
    public void presenceAnnounced(String mas, long incarnation, String[] names, String[] dfAgents, String[] dfServices,
            float period, boolean leaving, long sequence, long stamp, String keyId, byte[] mac, String publisher) {
        port.presenceAnnounced(mas, incarnation, names, dfAgents, dfServices, period, leaving, sequence, stamp, keyId,
                mac, publisher, "");
    }

    /** Periodic presence check with the processes our message publisher is connected to. */
    public void presenceTick(String[] linkedMas) {
        port.presenceTick(linkedMas);
    }
}
