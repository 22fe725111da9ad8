package rason.messaging.mqtt;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The tests' broker on a port somebody else holds: make test's other suites pick free ports
 * too, and a test must not talk to another suite's broker believing it its own.
 */
class MosquittoBrokerTest {

    @Test
    void aPortAnotherProcessHoldsIsRefusedNotTakenForTheBroker(@TempDir Path dir) throws Exception {
        try (ServerSocket other = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            MosquittoBroker.PortTaken e = assertThrows(MosquittoBroker.PortTaken.class,
                    () -> MosquittoBroker.start(dir, other.getLocalPort()).close());
            assertTrue(e.getMessage().contains("port " + other.getLocalPort()), e.getMessage());
        }
    }

    @Test
    void onAFreePortItTakesConnections(@TempDir Path dir) throws Exception {
        try (MosquittoBroker broker = MosquittoBroker.start(dir)) {
            try (java.net.Socket s = new java.net.Socket("127.0.0.1", broker.port())) {
                assertTrue(s.isConnected());
            }
        }
    }
}
