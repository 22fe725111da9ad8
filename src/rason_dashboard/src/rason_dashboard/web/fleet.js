// The fleet's pictures, drawn as inline SVG from the layouts the server made
// (sequence.py, fleet_map.py): the messages as a sequence diagram, the robots on a map, and
// every agent's intention stacks. Text goes in as textContent, never as markup.
'use strict';

const SVG_NS = 'http://www.w3.org/2000/svg';
const ROBOT_COLOURS = ['#1e88e5', '#e53935', '#43a047', '#8e24aa', '#fb8c00', '#00897b', '#6d4c41', '#3949ab'];

function svg(tag, attrs, ...children) {
  const e = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
  for (const c of children) e.append(c instanceof Node ? c : document.createTextNode(String(c)));
  return e;
}

function arrowHead(x1, x2, y) {
  // a triangle at x2 pointing away from x1
  const d = x2 >= x1 ? -1 : 1;
  return svg('polygon', { class: 'head', points: `${x2},${y} ${x2 + 7 * d},${y - 4} ${x2 + 7 * d},${y + 4}` });
}

function drawSequence(seq) {
  const root = svg('svg', { class: 'sequence', width: seq.width, height: seq.height,
    viewBox: `0 0 ${seq.width} ${seq.height}`, role: 'img', 'aria-label': 'messages between agents' });
  for (const lane of seq.lanes) {
    root.append(svg('g', { class: 'lane', 'data-lane': lane.name },
      svg('line', { x1: lane.x, y1: 22, x2: lane.x, y2: seq.height }),
      svg('text', { x: lane.x, y: 16, 'text-anchor': 'middle' }, lane.name)));
  }
  for (const row of seq.rows) {
    const g = svg('g', { class: 'msg step-' + row.step, 'data-step': row.step, 'data-from': row.sender,
      'data-to': row.receiver }, svg('title', {}, row.title));
    if (row.time != null) g.append(svg('text', { class: 'time', x: 2, y: row.y + 4 }, row.time.toFixed(1)));
    for (const a of row.arrows) {
      if (a.x1 === a.x2) {  // to itself: a small loop
        g.append(svg('path', { class: 'arrow', 'data-to': a.to, d: `M${a.x1},${row.y - 4} h18 v8 h-18` }));
        continue;
      }
      const end = a.x2 + (a.x2 > a.x1 ? -1 : 1);
      g.append(svg('line', { class: 'arrow', 'data-to': a.to, x1: a.x1, y1: row.y, x2: end, y2: row.y }),
        arrowHead(a.x1, end, row.y));
    }
    g.append(svg('text', { class: 'label', x: row.label_x, y: row.y - 5, 'text-anchor': 'middle' }, row.label));
    root.append(g);
  }
  return root;
}

function helpHead(x, y, ux, uy) {
  // a triangle at (x, y) pointing along the unit vector (ux, uy)
  const bx = x - 9 * ux, by = y - 9 * uy;
  return svg('polygon', { class: 'head', points: `${x},${y} ${bx - 4 * uy},${by + 4 * ux} ${bx + 4 * uy},${by - 4 * ux}` });
}

function drawMap(map, colours) {
  const root = svg('svg', { class: 'map', width: Math.round(map.width), height: Math.round(map.height),
    viewBox: `0 0 ${map.width} ${map.height}`, role: 'img', 'aria-label': 'the robots seen from above' });
  root.append(svg('rect', { class: 'floor', x: 0, y: 0, width: map.width, height: map.height }));
  for (const l of map.grid) root.append(svg('line', Object.assign({ class: 'grid' }, l)));
  for (const h of map.helps) {
    const dx = h.x2 - h.x1, dy = h.y2 - h.y1, n = Math.hypot(dx, dy) || 1, r = 12;  // stop at the robot's rim
    root.append(svg('g', { class: 'help', 'data-helper': h.helper, 'data-helped': h.helped },
      svg('title', {}, h.helper + ' helps ' + h.helped),
      svg('line', { x1: h.x1 + dx / n * r, y1: h.y1 + dy / n * r, x2: h.x2 - dx / n * r, y2: h.y2 - dy / n * r }),
      helpHead(h.x2 - dx / n * r, h.y2 - dy / n * r, dx / n, dy / n),
      svg('text', { x: (h.x1 + h.x2) / 2, y: (h.y1 + h.y2) / 2 - 4, 'text-anchor': 'middle' }, 'helps')));
  }
  for (const r of map.robots) {
    const colour = colours(r.name);
    const g = svg('g', { class: 'robot-mark', 'data-map-robot': r.name, style: 'color:' + colour });
    if (r.believed) {
      const b = r.believed;
      g.append(svg('g', { class: 'believed' + (b.frame ? ' odom-frame' : '') },
        svg('title', {}, r.name + ': believed pose (odometry)' + (b.frame ? ', in its odometry frame' : '')),
        svg('circle', { cx: b.x, cy: b.y, r: 9 }), svg('line', { x1: b.x, y1: b.y, x2: b.hx, y2: b.hy })));
    }
    const at = r.true || r.believed;
    if (r.true) {
      const t = r.true;
      g.append(svg('g', { class: 'true' }, svg('title', {}, r.name + ': true pose (simulator)'),
        svg('circle', { cx: t.x, cy: t.y, r: 9 }), svg('line', { x1: t.x, y1: t.y, x2: t.hx, y2: t.hy })));
    }
    g.append(svg('text', { class: 'name', x: at.x, y: at.y + 22, 'text-anchor': 'middle' }, r.name));
    root.append(g);
  }
  return root;
}

function intentionStacks(view) {
  // every agent's intentions, each stack innermost first, as in the cards but all together
  const rows = [];
  for (const r of view.robots) for (const a of r.agents) {
    const stacks = a.intentions.map(i => el('li', { class: 'stack', 'data-stack-intention': i.id },
      el('span', { class: 'state ' + i.state }, '#' + i.id + ' ' + i.state),
      el('ol', {}, ...i.plans.map(p => el('li', { class: 'frame', title: p }, p)))));
    rows.push(el('div', { class: 'stacks', 'data-stack-agent': a.name }, el('h4', {}, a.name, count(a.intentions.length)),
      stacks.length ? el('ul', {}, ...stacks) : el('p', { class: 'empty' }, 'no intention')));
  }
  return rows;
}

function robotColours(view) {
  const names = (view.map ? view.map.robots.map(r => r.name) : []);
  return name => ROBOT_COLOURS[Math.max(0, names.indexOf(name)) % ROBOT_COLOURS.length];
}

function drawFleet(view) {
  const map = document.getElementById('map');
  if (view.map) map.replaceChildren(drawMap(view.map, robotColours(view)));
  else map.replaceChildren(el('p', { class: 'empty' }, 'no poses (/<robot>/true_pose, /<robot>/odom)'));
  document.getElementById('helps').replaceChildren(...view.helps.map(h =>
    el('li', { class: 'helping' }, h.helper + ' helps ' + h.helped + ' (' + h.content + ')')));
  document.getElementById('stacks').replaceChildren(...intentionStacks(view));
  const seq = document.getElementById('sequence');
  // the newest message is at the bottom: stay there unless the user scrolled up to read
  const atBottom = seq.scrollTop + seq.clientHeight >= seq.scrollHeight - 8;
  if (view.sequence.rows.length) {
    const parts = [drawSequence(view.sequence)];
    if (view.sequence.left_out) parts.unshift(el('p', { class: 'empty' }, view.sequence.left_out + ' earlier messages not drawn'));
    seq.replaceChildren(...parts);
  } else seq.replaceChildren(el('p', { class: 'empty' }, 'no messages between robots yet'));
  if (atBottom) seq.scrollTop = seq.scrollHeight;
}
