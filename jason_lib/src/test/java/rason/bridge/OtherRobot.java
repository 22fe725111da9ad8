package rason.bridge;

import java.util.List;

import rason.messaging.FleetAuth;
import rason.messaging.FleetKeys;
import rason.messaging.WireMessage;

/**
 * Another robot's rason_mas in a bridge test: it shares the fleet key the bridge is given,
 * and announces its agents and sends their messages into the bridge signed, as the node
 * would hand them over from ROS.
 */
final class OtherRobot {

    final String masId;
    private final Bridge bridge;
    private final FleetAuth auth = new FleetAuth();

    /** Gives bridge the test key and makes masId a robot signing with it. */
    OtherRobot(Bridge bridge, String masId, String key) {
        this.bridge = bridge;
        this.masId = masId;
        bridge.fleet().requireKeyText(key, "test");
        auth.require(FleetKeys.parse(key, "test"));
        auth.setIncarnation(System.currentTimeMillis() * 1_000_000L);
    }

    /** Announces names (and their directory registrations), or that it is leaving. */
    void announce(String[] names, String[] dfAgents, String[] dfServices, boolean leaving) {
        FleetAuth.Signed p = auth.signPresence(masId, List.of(names), List.of(dfAgents), List.of(dfServices), 0.5f,
                leaving);
        bridge.fleet().presenceAnnounced(masId, p.incarnation(), names, dfAgents, dfServices, 0.5f, leaving, p.sequence(),
                p.stamp(), p.keyId(), p.mac(), masId, "");
    }

    /** Announces names without directory registrations. */
    void announce(String[] names, boolean leaving) {
        announce(names, new String[0], new String[0], leaving);
    }

    /** Delivers a message of its agent sender; returns what the bridge's deliverMessage returns. */
    int send(String sender, String receiver, String performative, String content, String inReplyTo) {
        WireMessage m = new WireMessage(masId, sender, "", receiver, performative, content, "mid" + System.nanoTime(),
                inReplyTo);
        FleetAuth.Signed s = auth.sign(m);
        return bridge.rosChannel().deliver(m.senderMas(), m.sender(), m.receiverMas(), m.receiver(), m.performative(),
                m.content(), m.msgId(), m.inReplyTo(), s.incarnation(), s.sequence(), s.stamp(), s.keyId(), s.mac(),
                masId);
    }
}
