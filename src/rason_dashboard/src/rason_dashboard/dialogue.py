"""The messages between robots read as dialogues: which step of a contract net (or of the
thesis's call for help) a message is, and who helps whom after a run of messages. Pure: the
sequence diagram colours its arrows by step, the map draws the help it derives.

Two vocabularies are known: the fleet program's contract net
(src/rason/agents/fleet/contract_net.asl: callForBids, propose, refuse, award, accepted,
declined, revoke, release, failed) and the case study's (cfp, propose, refuse,
acceptProposal, rejectProposal, done, failure; helpme, found, guideMe, stopGuiding, thanks)."""

#: (performative, functor) -> the step it is in a dialogue; anything else is 'other'.
STEPS = {
    ('achieve', 'callForBids'): 'call', ('tell', 'cfp'): 'call', ('achieve', 'helpme'): 'call',
    ('tell', 'propose'): 'bid', ('tell', 'refuse'): 'refuse',
    ('achieve', 'award'): 'award', ('tell', 'acceptProposal'): 'award',
    ('tell', 'accepted'): 'accept', ('tell', 'found'): 'accept', ('achieve', 'guideMe'): 'award',
    ('tell', 'declined'): 'decline', ('tell', 'rejectProposal'): 'decline',
    ('achieve', 'revoke'): 'end', ('achieve', 'release'): 'end', ('tell', 'failed'): 'end',
    ('tell', 'done'): 'end', ('tell', 'failure'): 'end', ('achieve', 'thanks'): 'end',
    ('achieve', 'stopGuiding'): 'end',
}

#: Messages that start a help, and which end it, as (performative, functor) -> whether the
#: sender is the helper (True) or the one helped (False).
HELP_STARTS = {('tell', 'accepted'): True, ('tell', 'found'): True,
               ('tell', 'acceptProposal'): False, ('achieve', 'guideMe'): False}
HELP_ENDS = {('achieve', 'revoke'): False, ('achieve', 'release'): False, ('tell', 'failed'): True,
             ('tell', 'done'): True, ('tell', 'failure'): True, ('achieve', 'thanks'): False,
             ('achieve', 'stopGuiding'): False}


def functor(content):
    """The functor of a Jason term as text: 'award' of 'award(contract(r1,2),observe(r1))'."""
    return content.split('(', 1)[0].strip()


#: The performative of Rason's delivery receipts (a robot's "got it" for a message sent).
RECEIPT = 'rason_receipt'


def step(message):
    """The dialogue step of a message record: call, bid, refuse, award, accept, decline, end,
    receipt (a delivery receipt, no step of any dialogue) or other."""
    if message['performative'] == RECEIPT:
        return 'receipt'
    return STEPS.get((message['performative'], functor(message['content'])), 'other')


def helping(messages):
    """Who helps whom after messages (records in time order, each with its time): the latest
    help each helper began (a contract net's accepted award, the thesis's found, a guideMe
    asked) that no later message between the same two ended (release, revoke, failed, done,
    failure, thanks, stopGuiding). A helper helps one robot at a time: a newer start replaces
    its older one. Returns [{'helper', 'helped', 'since', 'content'}] ordered by helper."""
    current = {}  # helper -> its help
    for m in messages:
        key = (m['performative'], functor(m['content']))
        if m['receiver'] == 'all':
            continue  # a help is between two robots
        if key in HELP_STARTS:
            helper, helped = (m['sender'], m['receiver']) if HELP_STARTS[key] else (m['receiver'], m['sender'])
            if helper != helped:
                current[helper] = {'helper': helper, 'helped': helped, 'since': m.get('time'),
                                   'content': m['content']}
        elif key in HELP_ENDS:
            helper, helped = (m['sender'], m['receiver']) if HELP_ENDS[key] else (m['receiver'], m['sender'])
            if helper in current and current[helper]['helped'] == helped:
                del current[helper]
    return [current[h] for h in sorted(current)]
