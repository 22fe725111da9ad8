"""One line per agent message or diagnosis, for people watching a run (rason_dialogue)."""

BROADCAST = 'all'


def format_message(sender, receiver, performative, content, in_reply_to=''):
    """``faulty -> all: achieve helpme``; replies to askOne/askAll are marked as such."""
    reply = ' (reply)' if in_reply_to else ''
    return '%s -> %s: %s %s%s' % (sender, receiver or BROADCAST, performative, content, reply)


def format_diagnosis(hardware_id, values):
    """``DIAGNOSIS faulty: both_actuators (no progress measured, ...)`` from the key/values
    of a rason/diagnosis DiagnosticStatus; None when it names no component."""
    values = dict(values)
    component = values.get('component')
    if not component:
        return None
    who = values.get('agent') or hardware_id.strip('/') or '?'
    evidence = values.get('evidence')
    return 'DIAGNOSIS %s: %s%s' % (who, component, ' (%s)' % evidence if evidence else '')
