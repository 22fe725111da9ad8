"""Messages read as dialogues: the contract net's steps, and who helps whom (no ROS)."""
from rason_dashboard.dialogue import functor, helping, step


def m(sender, receiver, performative, content, time=0.0):
    return {'sender': sender, 'receiver': receiver, 'performative': performative, 'content': content,
            'time': time}


def test_functor_of_terms():
    assert functor('award(contract(r1,2),observe(r1))') == 'award'
    assert functor('helpme') == 'helpme' and functor('') == ''


def test_the_fleet_contract_nets_steps():
    steps = [step(m('a', 'b', p, c)) for p, c in [
        ('achieve', 'callForBids(contract(a,1),observe(a))'), ('tell', 'propose(contract(a,1),2.5)'),
        ('tell', 'refuse(contract(a,1))'), ('achieve', 'award(contract(a,1),observe(a))'),
        ('tell', 'accepted(contract(a,1))'), ('tell', 'declined(contract(a,1))'),
        ('achieve', 'release(contract(a,1))'), ('tell', 'failed(contract(a,1))')]]
    assert steps == ['call', 'bid', 'refuse', 'award', 'accept', 'decline', 'end', 'end']


def test_the_case_studys_steps_and_anything_else():
    assert step(m('faulty', 'all', 'achieve', 'helpme')) == 'call'
    assert step(m('faulty', 'helper', 'tell', 'cfp(reach(faulty,1,0))')) == 'call'
    assert step(m('faulty', 'helper', 'tell', 'acceptProposal(reach(faulty,1,0))')) == 'award'
    assert step(m('a', 'b', 'tell', 'seenAt(1,2,3)')) == 'other'
    assert step(m('a', 'b', 'achieve', 'propose(x)')) == 'other'  # the performative counts too
    assert step(m('faulty', 'helper', 'rason_receipt', 'delivered')) == 'receipt'


def test_an_accepted_award_makes_a_helper_until_released():
    call = [m('r4', 'r1', 'achieve', 'award(contract(r4,1),observe(r4))', 1.0),
            m('r1', 'r4', 'tell', 'accepted(contract(r4,1))', 2.0)]
    assert helping(call[:1]) == []  # an award alone binds nobody
    assert helping(call) == [{'helper': 'r1', 'helped': 'r4', 'since': 2.0, 'content': 'accepted(contract(r4,1))'}]
    assert helping(call + [m('r4', 'r1', 'achieve', 'release(contract(r4,1))')]) == []
    assert helping(call + [m('r1', 'r4', 'tell', 'failed(contract(r4,1))')]) == []
    assert helping(call + [m('r4', 'r2', 'achieve', 'release(contract(r4,2))')]) != []  # another pair


def test_two_helps_at_once_and_a_helper_moving_on():
    both = [m('r1', 'r4', 'tell', 'accepted(contract(r4,1))'), m('r2', 'r3', 'tell', 'accepted(contract(r3,1))')]
    assert [(h['helper'], h['helped']) for h in helping(both)] == [('r1', 'r4'), ('r2', 'r3')]
    moved = both + [m('r1', 'r3', 'tell', 'accepted(contract(r3,2))')]
    assert [(h['helper'], h['helped']) for h in helping(moved)] == [('r1', 'r3'), ('r2', 'r3')]
    # the end of r1's first help, late: its newer help stands
    assert len(helping(moved + [m('r4', 'r1', 'achieve', 'revoke(contract(r4,1))')])) == 2


def test_the_thesis_dialogue_and_the_case_studys_delegation():
    thesis = [m('faulty', 'all', 'achieve', 'helpme'), m('helper', 'faulty', 'tell', 'found(faulty)')]
    assert [(h['helper'], h['helped']) for h in helping(thesis)] == [('helper', 'faulty')]
    assert helping(thesis + [m('faulty', 'helper', 'achieve', 'thanks')]) == []
    delegated = [m('faulty', 'helper', 'tell', 'acceptProposal(reach(faulty,1,0))')]
    assert [(h['helper'], h['helped']) for h in helping(delegated)] == [('helper', 'faulty')]
    assert helping(delegated + [m('helper', 'faulty', 'tell', 'done(reach(faulty,1,0))')]) == []
