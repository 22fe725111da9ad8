"""Presence announcements, pulses and agent messages signed by Java's fleet authentication
(through Java's ``RosTopicChannel``), as the ROS messages to publish; no rospy."""
from rason_msgs.msg import Presence, Pulse

from rason_bridge.fleet_auth import to_uint64


def presence(channel, agent_names, mas_id, period, leaving):
    """The next announcement of this process's agents and registrations, signed.

    Call it in publishing order (one at a time): the sequence numbers must arrive increasing.
    """
    # dfAnnounced first: it clears the "announce at once" flag, so an agent or registration
    # changing after it queues another announcement instead of going unannounced
    df = channel.announced()
    agents = [str(n) for n in agent_names]
    df_agents, df_services = [str(a) for a in df.agents()], [str(s) for s in df.services()]
    signed = channel.signPresence(agents, df_agents, df_services, period, leaving)
    return Presence(mas_id=mas_id, incarnation=to_uint64(signed.incarnation()), agents=agents,
                    df_agents=df_agents, df_services=df_services, period=period, leaving=leaving,
                    sequence=to_uint64(signed.sequence()), stamp=to_uint64(signed.stamp()),
                    key_id=str(signed.keyId()), mac=bytes(signed.mac()))


def pulse(channel, mas_id):
    """Our next pulse, signed (in publishing order)."""
    signed = channel.signPulse()
    return Pulse(mas_id=mas_id, incarnation=to_uint64(signed.incarnation()), sequence=to_uint64(signed.sequence()),
                 stamp=to_uint64(signed.stamp()), key_id=str(signed.keyId()), mac=bytes(signed.mac()))


def sign_message(channel, msg):
    """Fill in the authentication fields of an ``AgentMessage`` (in publishing order); returns it."""
    signed = channel.sign(msg.receiver_mas, msg.sender, msg.receiver, msg.performative, msg.content,
                          msg.msg_id, msg.in_reply_to)
    msg.incarnation, msg.sequence = to_uint64(signed.incarnation()), to_uint64(signed.sequence())
    msg.stamp, msg.key_id, msg.mac = to_uint64(signed.stamp()), str(signed.keyId()), bytes(signed.mac())
    return msg
