package rason.messaging;

import rason.core.Clock;
import rason.core.InputLimits;
import rason.core.RateLimitedLog;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.logging.Logger;

/** Another rason_mas process of the fleet, as the tests need one: it signs its presence and messages with its keys. */
final class SigningPeer {

    /** Test keys (32 bytes and more; never used outside tests). */
    static final String KEY_A = "test-fleet-key-A-0123456789abcdef0123456789abcdef";
    static final String KEY_B = "test-fleet-key-B-fedcba9876543210fedcba9876543210";

    static FleetKeys keys(String... secrets) {
        return FleetKeys.parse(String.join("\n", secrets), "test");
    }

    final String mas;
    final FleetAuth auth;

    SigningPeer(String mas, long incarnation, FleetKeys keys) {
        this.mas = mas;
        this.auth = new FleetAuth();
        auth.require(keys);
        auth.setIncarnation(incarnation);
    }

    SigningPeer(String mas, long incarnation) {
        this(mas, incarnation, keys(KEY_A));
    }

    /** Its next presence, as published, delivered to fleet. */
    void announce(Fleet fleet, boolean leaving, String... agents) {
        FleetAuth.Signed s = auth.signPresence(mas, List.of(agents), 0.5f, leaving);
        fleet.presenceAnnounced(mas, agents, new String[0], new String[0], leaving, 0.5f, s, mas, "");
    }

    /** Its next presence with directory registrations (dfAgents[i] provides dfServices[i]), delivered to fleet. */
    void announce(Fleet fleet, String[] agents, String[] dfAgents, String[] dfServices) {
        FleetAuth.Signed s = auth.signPresence(mas, List.of(agents), List.of(dfAgents), List.of(dfServices), 0.5f, false);
        fleet.presenceAnnounced(mas, agents, dfAgents, dfServices, false, 0.5f, s, mas, "");
    }

    WireMessage message(String sender, String receiver, String performative, String content) {
        return new WireMessage(mas, sender, "", receiver, performative, content, "mid", "");
    }

    /** Its next message, delivered to fleet as published by this peer. */
    Fleet.Incoming send(Fleet fleet, String sender, String receiver, String performative, String content) {
        WireMessage m = message(sender, receiver, performative, content);
        return fleet.accept(m, auth.sign(m), mas, false);
    }

    /** A fleet (this process) with the test key A and a listener that ignores everything. */
    static Fleet fleet(Logger logger, RateLimitedLog limited, String masId, long incarnation) {
        Fleet f = new Fleet(logger, stopsInto(new ArrayList<>()), limited, authWithKeyA(), new InputLimits(), Clock.WALL);
        f.setMasId(masId);
        f.setIncarnation(incarnation);
        return f;
    }

    /** Authentication required, with the test key A. */
    static FleetAuth authWithKeyA() {
        FleetAuth auth = new FleetAuth();
        auth.require(keys(KEY_A));
        return auth;
    }

    /** A fleet listener that keeps the reasons it is told to stop in stops and ignores the rest. */
    static FleetListener stopsInto(List<String> stops) {
        return recording(stops, new ArrayList<>());
    }

    /** A fleet listener that keeps the stop reasons and the directory's notices it is told. */
    static FleetListener recording(List<String> stops, List<FleetDirectory.Notice> notices) {
        return new FleetListener() {
            @Override
            public void reachableChanged() {
            }

            @Override
            public void receiversLost(Collection<String> names) {
            }

            @Override
            public void mustStop(String why) {
                stops.add(why);
            }

            @Override
            public void providersChanged(List<FleetDirectory.Notice> heard) {
                notices.addAll(heard);
            }
        };
    }
}
