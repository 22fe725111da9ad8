// The Rason dashboard page: draws /api/view (every robot's agents, the messages between
// robots, the rason/* statuses). Live: polls twice a second. Replay: the slider picks the
// time. Everything is drawn with textContent, never as HTML, since agents' text is data.
'use strict';

const POLL_MS = 500;
let span = null;          // [first, last] time of the data (replay)
let live = true;
let request = 0;          // newer requests win over late answers

function el(tag, attrs, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  for (const c of children) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
  return e;
}

function list(title, items, cls) {
  const ul = el('ul', {});
  if (!items.length) ul.append(el('li', { class: 'empty' }, 'none'));
  for (const i of items) ul.append(el('li', { class: cls }, i));
  return [el('h4', {}, title), ul];
}

function agentView(a) {
  const div = el('div', { class: 'agent', 'data-agent': a.name });
  div.append(el('h3', {}, a.name + ' ', el('small', {}, 'cycle ' + a.cycle)));
  div.append(...list('Beliefs', a.beliefs, 'belief'));
  div.append(...list('Goals', a.goals, 'goal'));
  const ints = el('ul', {});
  if (!a.intentions.length) ints.append(el('li', { class: 'empty' }, 'none'));
  for (const i of a.intentions) {
    const li = el('li', { class: 'intention' }, el('span', { class: 'state' }, '#' + i.id + ' ' + i.state));
    const plans = el('ul', {});
    for (const p of i.plans) plans.append(el('li', { class: 'plan' }, p));
    li.append(plans);
    ints.append(li);
  }
  div.append(el('h4', {}, 'Intentions'), ints);
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
    for (const a of r.agents) card.append(agentView(a));
    return card;
  }));
  document.getElementById('messages').replaceChildren(...view.messages.map(m =>
    el('li', { class: 'dialogue', 'data-line': m.line }, el('span', { class: 'time' }, m.time.toFixed(2)), m.line)));
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
