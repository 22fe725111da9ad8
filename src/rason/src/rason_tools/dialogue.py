"""One line per agent message or diagnosis, for people watching a run (rason_dialogue)."""

BROADCAST = 'all'
#: The receiving process's acknowledgement of a message (rason.messaging.Receipts): the fleet's
#: bookkeeping, not something an agent said.
RECEIPT = 'rason_receipt'


def format_message(sender, receiver, performative, content, in_reply_to=''):
    """``faulty -> all: achieve helpme``; replies to askOne/askAll are marked as such; None for
    a receipt."""
    if performative == RECEIPT:
        return None
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


def format_mission(hardware_id, values):
    """``MISSION faulty: completed by helper (recovery delegate after both_actuators)`` from
    the key/values of a rason/mission DiagnosticStatus; None when it says nothing."""
    values = dict(values)
    completed = values.get('completed')
    if completed not in ('true', 'false'):
        return None
    who = values.get('agent') or hardware_id.strip('/') or '?'
    how = '(recovery %s after %s)' % (values.get('recovery', '?'), values.get('diagnosis', '?'))
    if completed == 'true':
        return 'MISSION %s: completed by %s %s' % (who, values.get('by') or '?', how)
    return 'MISSION %s: not completed %s' % (who, how)
