// The Rason dashboard page: draws /api/view (every robot's agents, the messages between
// robots, the rason/* statuses; the fleet's pictures with fleet.js). Live: polls twice a second. Replay: the slider picks the
// time. Everything is drawn with textContent, never as HTML, since agents' text is data.
'use strict';

const POLL_MS = 500;
let span = null;          // [first, last] time of the data (replay)
let live = true;
let request = 0;          // newer requests win over late answers
const openRules = new Set();  // "robot agent" whose rules the user opened: kept open across redraws

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  for (const c of children) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
  return e;
}

function list(title, items, cls, added, removed) {
  // added: entries new since the robot's snapshot before (marked); removed: gone since (struck out)
  const fresh = new Set(added || []);
  const ul = el('ul', {});
  if (!items.length && !(removed || []).length) ul.append(el('li', { class: 'empty' }, 'none'));
  for (const i of items) ul.append(el('li', { class: fresh.has(i) ? cls + ' added' : cls }, i));
  for (const i of removed || []) ul.append(el('li', { class: 'removed', 'data-removed': cls, title: 'gone since the step before' }, i));
  return [el('h4', {}, title, count(items.length)), ul];
}

function count(n) {
  return el('span', { class: 'count' }, String(n));
}

function changeSummary(c) {
  if (!c || c.new_agent) return null;
  const parts = [];
  const n = (xs, what) => { if (xs.length) parts.push(xs.length + ' ' + what); };
  n(c.beliefs_added, 'belief(s) added'); n(c.beliefs_removed, 'removed');
  n(c.goals_added, 'goal(s) new'); n(c.goals_removed, 'goal(s) gone');
  n(c.intentions_changed, 'intention(s) changed'); n(c.intentions_ended, 'ended');
  n(c.rules_added.concat(c.rules_removed), 'rule change(s)');
  return el('p', { class: 'changes' }, parts.length ? 'since the step before: ' + parts.join(', ') : 'no change since the step before');
}

function rulesView(key, rules, added) {
  const fresh = new Set(added || []);
  const ul = el('ul', {});
  for (const r of rules) ul.append(el('li', { class: fresh.has(r) ? 'rule added' : 'rule' }, r));
  const details = el('details', { class: 'rules' }, el('summary', {}, 'Rules ', count(rules.length)), ul);
  details.open = openRules.has(key);
  details.addEventListener('toggle', () => details.open ? openRules.add(key) : openRules.delete(key));
  return details;
}

function agentView(robot, a) {
  const c = a.changes || {};
  const div = el('div', { class: 'agent', 'data-agent': a.name });
  div.append(el('h3', {}, a.name + ' ', el('small', {}, 'cycle ' + a.cycle)));
  const summary = changeSummary(a.changes);
  if (summary) div.append(summary);
  div.append(...list('Goals', a.goals, 'goal', c.goals_added, c.goals_removed));
  div.append(...list('Beliefs', a.beliefs, 'belief', c.beliefs_added, c.beliefs_removed));
  const rules = a.rules || [];
  if (rules.length)  // collapsed: a program's rules rarely change, and would bury the beliefs
    div.append(rulesView(robot + ' ' + a.name, rules, c.rules_added));
  const changed = new Set(c.intentions_changed || []);
  const ints = el('ul', { class: 'intentions' });
  if (!a.intentions.length && !(c.intentions_ended || []).length) ints.append(el('li', { class: 'empty' }, 'none'));
  for (const i of a.intentions) {
    const li = el('li', { class: changed.has(i.id) ? 'intention changed' : 'intention', 'data-intention': i.id },
      el('span', { class: 'state ' + i.state }, '#' + i.id + ' ' + i.state));
    const plans = el('ul', {});
    for (const p of i.plans) plans.append(el('li', { class: 'plan' }, p));
    li.append(plans);
    ints.append(li);
  }
  for (const i of c.intentions_ended || [])
    ints.append(el('li', { class: 'removed', 'data-removed': 'intention' }, '#' + i.id + ' ended' + (i.plans.length ? ': ' + i.plans[i.plans.length - 1] : '')));
  div.append(el('h4', {}, 'Intentions', count(a.intentions.length)), ints);
  div.append(...list('Pending actions',
    a.actions.map(x => x.action + ' (id ' + x.id + ', ' + x.age.toFixed(1) + ' s' + (x.held ? ', held' : '') + ')'),
    'action'));
  div.append(...list('Recent events', a.events.slice().reverse(), 'event'));
  div.append(...list('Recent messages', a.messages.slice().reverse(), 'message'));
  if (a.omitted) div.append(el('p', { class: 'empty' }, a.omitted + ' entries left out'));
  return div;
}

function draw(view) {
  document.getElementById('mode').textContent = view.mode;
  document.getElementById('clock').textContent = view.time == null ? '' : 't = ' + view.time.toFixed(2) + ' s';
  const robots = document.getElementById('robots');
  robots.replaceChildren(...view.robots.map(r => {
    const card = el('div', { class: 'robot', 'data-robot': r.mas_id }, el('h2', {}, r.mas_id));
    if (r.inspector_url && r.inspector_url.startsWith('http://127.0.0.1:'))  // Jason's, on this machine
      card.append(el('a', { class: 'inspector', href: r.inspector_url, target: '_blank' }, "Jason's mind inspector"));
    if (!r.agents.length) card.append(el('p', { class: 'empty' }, 'no agents'));
    for (const a of r.agents) card.append(agentView(r.mas_id, a));
    return card;
  }));
  document.getElementById('messages').replaceChildren(...view.messages.map(m =>
    el('li', { class: 'dialogue', 'data-line': m.line }, el('span', { class: 'time' }, m.time.toFixed(2)), m.line)));
  drawFleet(view);
  document.getElementById('statuses').replaceChildren(...view.statuses.map(s =>
    el('span', { class: 'status ' + s.level, 'data-status': s.name }, s.name + ': ' + s.message)));
  if (view.mode === 'replay' && view.span) {
    span = view.span;
    live = false;
    document.getElementById('replay').hidden = false;
  }
}

async function fetchView(t) {
  const mine = ++request;
  const url = t == null ? 'api/view' : 'api/view?t=' + encodeURIComponent(t);
  try {
    const r = await fetch(url, { cache: 'no-store' });
    if (!r.ok) throw new Error(r.status + ' ' + (await r.text()));
    const view = await r.json();
    if (mine === request) draw(view);
  } catch (e) {
    document.getElementById('mode').textContent = 'no answer from the dashboard: ' + e.message;
  }
}

function sliderTime() {
  const s = document.getElementById('slider');
  return span[0] + (span[1] - span[0]) * s.value / s.max;
}

document.getElementById('slider').addEventListener('input', () => {
  if (!span) return;
  const t = sliderTime();
  document.getElementById('position').textContent = (t - span[0]).toFixed(2) + ' s of ' + (span[1] - span[0]).toFixed(2);
  fetchView(t);
});

async function loop() {
  if (live) await fetchView(null);
  if (live) setTimeout(loop, POLL_MS);
}
loop();
