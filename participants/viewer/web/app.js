// turf-viewer's page: draws the field to scale from the viewer's WebSocket
// messages (participants/viewer/viewer_json.h) and sends the user's controls
// back (participants/viewer/page_request.h). Plain JavaScript and Canvas 2D.
// Legged scenes are drawn by legged.js (window.turfLegged).
'use strict';

(() => {
  const TEAM_FILL = { blue: '#2f6fed', yellow: '#f2d21b' };
  const TEAM_TEXT = { blue: '#ffffff', yellow: '#111111' };
  const BALL = '#ff7a1a';
  const SEND_EVERY_MS = 33;  // teleports while dragging: ~30 a second
  const SNAP_DISTANCE = 0.5;  // m: a jump this large (teleport, reset) is not interpolated
  // Throwing the ball (right- or shift-drag): the arrow from the ball to the
  // pointer, times THROW_GAIN, is its velocity, up to MAX_THROW (page_request.h's kMaxThrowSpeed).
  const THROW_GAIN = 2;  // (m/s) per m of arrow
  const MAX_THROW = 8;  // m/s

  const canvas = document.getElementById('field');
  const ctx = canvas.getContext('2d');
  const $ = (id) => document.getElementById(id);

  const Legged = window.turfLegged;
  const LEGGED_REACH = 0.35;  // m from a legged robot's root that grabs it

  const view = {
    field: null,            // SSL scenes: the field message
    legged: null,           // legged scenes: the legged message (robots' shapes, 3D field)
    leggedDrawn: [],        // legged robots as last drawn (outlines in metres)
    prev: null, prevAt: 0,  // the two newest states and when they arrived (performance.now())
    cur: null, curAt: 0,
    mode: 'truth',          // truth | cameras | both
    drag: null,             // {kind: 'ball'|'throw'|'robot'|'legged', team, id, x, y, yaw, rotate, lastSent}
    ws: null,
    scale: 1, ox: 0, oy: 0, dpr: 1,
    drawn: false,           // a state is on the canvas since the last layout
    received: {},           // messages by type, for the console and tests
    recording: false,       // turf-viewer --recording: states come from recording.js, controls are hidden
  };

  // --- geometry: field metres <-> canvas CSS pixels ---

  function layout() {
    const rect = canvas.getBoundingClientRect();
    view.dpr = window.devicePixelRatio || 1;
    canvas.width = Math.max(1, Math.round(rect.width * view.dpr));
    canvas.height = Math.max(1, Math.round(rect.height * view.dpr));
    const f = view.field;
    let halfX = f ? f.length / 2 + f.boundary_goal + 0.05 : 5;
    let halfY = f ? f.width / 2 + f.boundary + 0.05 : 3.5;
    if (view.legged) {
      const e = Legged.extents(view.legged, view.cur ? Legged.robots(view.legged, view.cur.links) : []);
      [halfX, halfY] = [e.hx, e.hy];
    }
    view.half = [halfX, halfY];
    view.scale = Math.min(rect.width / (2 * halfX), rect.height / (2 * halfY));
    view.ox = rect.width / 2;
    view.oy = rect.height / 2;
    view.drawn = false;  // resizing cleared the canvas
  }
  const sceneKnown = () => !!(view.field || view.legged);
  const ballRadius = () => (view.field ? view.field.ball_radius
    : view.legged && view.legged.field ? view.legged.field.ball_radius : 0.05);
  const toCanvas = (x, y) => [view.ox + x * view.scale, view.oy - y * view.scale];
  const toField = (cx, cy) => [(cx - view.ox) / view.scale, (view.oy - cy) / view.scale];
  const px = (metres) => metres * view.scale;

  // --- drawing ---

  function drawField(f) {
    const wallX = f.length / 2 + f.boundary_goal;
    const wallY = f.width / 2 + f.boundary;
    ctx.fillStyle = '#0e1013';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    const [wx, wy] = toCanvas(-wallX, wallY);
    ctx.fillStyle = '#1d6b35';
    ctx.fillRect(wx, wy, px(2 * wallX), px(2 * wallY));
    ctx.strokeStyle = '#3b2a1a';
    ctx.lineWidth = Math.max(2, px(0.03));
    ctx.strokeRect(wx, wy, px(2 * wallX), px(2 * wallY));

    ctx.strokeStyle = 'rgba(255,255,255,0.92)';
    ctx.lineWidth = Math.max(1, px(f.line));
    const L = f.length / 2, W = f.width / 2;
    const line = (x0, y0, x1, y1) => {
      const [a, b] = toCanvas(x0, y0), [c, d] = toCanvas(x1, y1);
      ctx.beginPath(); ctx.moveTo(a, b); ctx.lineTo(c, d); ctx.stroke();
    };
    const rect = (x0, y0, x1, y1) => {
      const [a, b] = toCanvas(Math.min(x0, x1), Math.max(y0, y1));
      ctx.strokeRect(a, b, px(Math.abs(x1 - x0)), px(Math.abs(y1 - y0)));
    };
    rect(-L, -W, L, W);
    line(0, -W, 0, W);
    line(-L, 0, L, 0);
    const [cx, cy] = toCanvas(0, 0);
    ctx.beginPath(); ctx.arc(cx, cy, px(f.center_radius), 0, 2 * Math.PI); ctx.stroke();
    for (const side of [-1, 1]) {
      rect(side * L, -f.penalty_width / 2, side * (L - f.penalty_depth), f.penalty_width / 2);
      // Goal: back and side walls behind the goal line.
      ctx.save();
      ctx.strokeStyle = '#d8d8d8';
      ctx.lineWidth = Math.max(2, px(0.02));
      const g = f.goal_width / 2, back = side * (L + f.goal_depth);
      ctx.beginPath();
      const p = [toCanvas(side * L, g), toCanvas(back, g), toCanvas(back, -g), toCanvas(side * L, -g)];
      ctx.moveTo(...p[0]); ctx.lineTo(...p[1]); ctx.lineTo(...p[2]); ctx.lineTo(...p[3]);
      ctx.stroke();
      ctx.restore();
    }
  }

  function drawCameraAreas(f) {
    ctx.save();
    ctx.setLineDash([6, 6]);
    ctx.strokeStyle = 'rgba(160,200,255,0.5)';
    ctx.fillStyle = 'rgba(160,200,255,0.7)';
    ctx.lineWidth = 1;
    ctx.font = '11px "DejaVu Sans", sans-serif';
    for (const c of f.cameras || []) {
      const [a, b] = toCanvas(c.min[0], c.max[1]);
      ctx.strokeRect(a + 2, b + 2, px(c.max[0] - c.min[0]) - 4, px(c.max[1] - c.min[1]) - 4);
      ctx.fillText(`camera ${c.id}`, a + 6, b + 14);
    }
    ctx.restore();
  }

  function robotPath(x, y, yaw, r) {
    const [cx, cy] = toCanvas(x, y);
    const R = px(r);
    const phi = Math.acos(0.08 / 0.09);  // flat front: 0.08 m of a 0.09 m radius
    ctx.beginPath();
    ctx.arc(cx, cy, R, -yaw + phi, -yaw - phi + 2 * Math.PI);
    ctx.closePath();
    return [cx, cy, R];
  }

  function drawRobot(rb, r, style) {
    const [cx, cy, R] = robotPath(rb.x, rb.y, rb.yaw, r);
    ctx.save();
    ctx.globalAlpha = style.alpha;
    if (style.outline) {
      ctx.fillStyle = 'rgba(0,0,0,0.25)';
      ctx.fill();
      ctx.lineWidth = 2;
      ctx.strokeStyle = TEAM_FILL[rb.team];
      ctx.stroke();
    } else {
      ctx.fillStyle = TEAM_FILL[rb.team];
      ctx.fill();
      ctx.lineWidth = 1;
      ctx.strokeStyle = '#0b0b0b';
      ctx.stroke();
    }
    // Heading: the flat front, drawn thick, and a tick from it outwards.
    const phi = Math.acos(0.08 / 0.09);
    const h = -rb.yaw;
    ctx.beginPath();
    ctx.moveTo(cx + Math.cos(h - phi) * R, cy + Math.sin(h - phi) * R);
    ctx.lineTo(cx + Math.cos(h + phi) * R, cy + Math.sin(h + phi) * R);
    ctx.moveTo(cx + Math.cos(h) * R * 0.89, cy + Math.sin(h) * R * 0.89);
    ctx.lineTo(cx + Math.cos(h) * R * 1.35, cy + Math.sin(h) * R * 1.35);
    ctx.lineWidth = Math.max(2, R * 0.22);
    ctx.lineCap = 'round';
    ctx.strokeStyle = style.outline ? TEAM_FILL[rb.team] : '#e53935';
    ctx.stroke();
    ctx.fillStyle = style.outline ? '#ffffff' : TEAM_TEXT[rb.team];
    ctx.font = `bold ${Math.max(9, Math.round(R * 0.95))}px "DejaVu Sans", sans-serif`;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillText(String(rb.id), cx, cy + 0.5);
    ctx.restore();
  }

  function drawBall(x, y, z, r, style) {
    const [cx, cy] = toCanvas(x, y);
    const R = Math.max(4, px(r));
    ctx.save();
    ctx.globalAlpha = style.alpha;
    const flying = z > r + 0.01;
    if (flying) {  // shadow on the ground, the ball larger the higher it is, and its height
      ctx.fillStyle = 'rgba(0,0,0,0.45)';
      ctx.beginPath(); ctx.arc(cx, cy, R, 0, 2 * Math.PI); ctx.fill();
    }
    const grow = flying ? 1 + Math.min(z, 3) * 0.6 : 1;
    const lift = flying ? Math.min(px(z) * 0.35, 40) : 0;
    ctx.beginPath();
    ctx.arc(cx, cy - lift, R * grow, 0, 2 * Math.PI);
    if (style.outline) {
      ctx.strokeStyle = BALL; ctx.lineWidth = 2; ctx.stroke();
    } else {
      ctx.fillStyle = BALL; ctx.fill();
      ctx.strokeStyle = '#3a1a00'; ctx.lineWidth = 1; ctx.stroke();
    }
    if (flying && !style.outline) {
      ctx.fillStyle = '#ffffff';
      ctx.font = '12px "DejaVu Sans", sans-serif';
      ctx.textAlign = 'left';
      ctx.fillText(`${z.toFixed(2)} m`, cx + R * grow + 4, cy - lift - 4);
    }
    ctx.restore();
  }

  // A throw being aimed: an arrow from the ball along its velocity-to-be, with the speed.
  function drawThrow(s) {
    const t = throwOf(view.drag, s);
    if (!t) return;
    const [ax, ay] = toCanvas(t.x, t.y);
    const [bx, by] = toCanvas(t.x + t.vx / THROW_GAIN, t.y + t.vy / THROW_GAIN);
    const angle = Math.atan2(by - ay, bx - ax);
    ctx.save();
    ctx.strokeStyle = ctx.fillStyle = '#ffffff';
    ctx.lineWidth = 2;
    ctx.setLineDash([5, 4]);
    ctx.beginPath(); ctx.moveTo(ax, ay); ctx.lineTo(bx, by); ctx.stroke();
    ctx.setLineDash([]);
    ctx.beginPath();
    ctx.moveTo(bx, by);
    ctx.lineTo(bx - 12 * Math.cos(angle - 0.4), by - 12 * Math.sin(angle - 0.4));
    ctx.lineTo(bx - 12 * Math.cos(angle + 0.4), by - 12 * Math.sin(angle + 0.4));
    ctx.closePath(); ctx.fill();
    ctx.font = 'bold 12px "DejaVu Sans", sans-serif';
    ctx.textAlign = 'left';
    ctx.fillText(`${Math.hypot(t.vx, t.vy).toFixed(1)} m/s`, bx + 8, by - 8);
    ctx.restore();
  }

  // The state to draw: the newest, eased from the one before over one
  // message interval, so 60 messages a second look smooth at any refresh rate.
  function blended() {
    const cur = view.cur;
    if (!cur) return null;
    const prev = view.prev;
    const gap = view.curAt - view.prevAt;
    if (!prev || gap <= 0 || gap > 200) return cur;
    const a = Math.min(1, (performance.now() - view.curAt) / gap);
    if (a >= 1) return cur;
    const lerp = (p, q) => p + (q - p) * a;
    const before = new Map(prev.robots.map((r) => [`${r.team}${r.id}`, r]));
    const robots = cur.robots.map((r) => {
      const p = before.get(`${r.team}${r.id}`);
      if (!p || !p.on || !r.on || Math.hypot(r.p[0] - p.p[0], r.p[1] - p.p[1]) > SNAP_DISTANCE) return r;
      let dyaw = r.yaw - p.yaw;
      dyaw = Math.atan2(Math.sin(dyaw), Math.cos(dyaw));
      return { ...r, p: [lerp(p.p[0], r.p[0]), lerp(p.p[1], r.p[1])], yaw: p.yaw + dyaw * a };
    });
    let ball = cur.ball;
    if (prev.ball && cur.ball) {
      const bp = prev.ball.p, bc = cur.ball.p;
      if (Math.hypot(bc[0] - bp[0], bc[1] - bp[1]) <= SNAP_DISTANCE)
        ball = { ...cur.ball, p: [lerp(bp[0], bc[0]), lerp(bp[1], bc[1]), lerp(bp[2], bc[2])] };
    }
    return { ...cur, robots, ball, links: blendLinks(prev.links, cur.links, a) };
  }

  // Legged robots' body poses eased like the SSL robots: positions lerped,
  // quaternions lerped and normalised (nlerp), unless the root jumped.
  function blendLinks(prev, cur, a) {
    if (!prev || !cur) return cur;
    const out = {};
    for (const [name, c] of Object.entries(cur)) {
      const p = prev[name];
      if (!p || p.length !== c.length || Math.hypot(c[0] - p[0], c[1] - p[1]) > SNAP_DISTANCE) { out[name] = c; continue; }
      const b = new Array(c.length);
      for (let i = 0; i < c.length; i += 7) {
        for (let k = 0; k < 3; ++k) b[i + k] = p[i + k] + (c[i + k] - p[i + k]) * a;
        const sign = p[i + 3] * c[i + 3] + p[i + 4] * c[i + 4] + p[i + 5] * c[i + 5] + p[i + 6] * c[i + 6] < 0 ? -1 : 1;
        let n = 0;
        for (let k = 3; k < 7; ++k) { b[i + k] = p[i + k] * sign + (c[i + k] - p[i + k] * sign) * a; n += b[i + k] * b[i + k]; }
        n = Math.sqrt(n) || 1;
        for (let k = 3; k < 7; ++k) b[i + k] /= n;
      }
      out[name] = b;
    }
    return out;
  }

  function drawLegged() {
    const T = { ctx, toCanvas, toField, px, width: canvas.width / view.dpr, height: canvas.height / view.dpr };
    Legged.drawGround(T, view.legged);
    const s = blended();
    if (!s) { view.leggedDrawn = []; return; }
    const d = view.drag;
    const moved = {};
    if (d && d.kind === 'legged') moved[d.name] = [d.x - d.root[0], d.y - d.root[1]];
    view.leggedDrawn = Legged.robots(view.legged, s.links, moved);
    // A robot beyond the shown area (walked off, teleported): show more.
    const [hx, hy] = view.half;
    if (!d && view.leggedDrawn.some((r) => Math.abs(r.root[0]) > hx || Math.abs(r.root[1]) > hy)) {
      layout();
      return;
    }
    Legged.drawRobots(T, view.leggedDrawn, { alpha: 1, highlight: d && d.kind === 'legged' ? d.name : null });
    if (d && d.kind === 'ball') drawBall(d.x, d.y, 0, ballRadius(), { alpha: 1 });
    else if (s.ball) drawBall(s.ball.p[0], s.ball.p[1], s.ball.p[2], ballRadius(), { alpha: 1 });
    drawThrow(s);
    view.drawn = true;
  }

  function draw() {
    ctx.setTransform(view.dpr, 0, 0, view.dpr, 0, 0);
    if (view.legged) { drawLegged(); return; }
    const f = view.field;
    if (!f) {
      ctx.fillStyle = '#0e1013';
      ctx.fillRect(0, 0, canvas.width, canvas.height);
      ctx.fillStyle = '#9aa3ad';
      ctx.font = '16px "DejaVu Sans", sans-serif';
      ctx.fillText('waiting for the field (or legged scene) from turf-sim…', 20, 30);
      return;
    }
    drawField(f);
    const s = blended();
    if (!s) return;
    const truth = view.mode !== 'cameras';
    const cameras = view.mode !== 'truth';
    if (cameras) drawCameraAreas(f);
    if (truth) {
      const alpha = cameras ? 0.45 : 1;
      for (const r of s.robots) {
        if (!r.on) continue;
        const d = view.drag;
        const dragged = d && d.kind === 'robot' && d.team === r.team && d.id === r.id;
        const shown = dragged ? { team: r.team, id: r.id, x: d.x, y: d.y, yaw: d.yaw }
          : { team: r.team, id: r.id, x: r.p[0], y: r.p[1], yaw: r.yaw };
        drawRobot(shown, f.robot_radius, { alpha });
      }
      const d = view.drag;
      if (d && d.kind === 'ball') drawBall(d.x, d.y, 0, f.ball_radius, { alpha });
      else drawBall(s.ball.p[0], s.ball.p[1], s.ball.p[2], f.ball_radius, { alpha });
    }
    drawThrow(s);
    view.drawn = true;
    if (cameras) {
      for (const det of s.detections || []) {
        for (const r of det.robots) {
          drawRobot({ team: r.team, id: r.id, x: r.p[0], y: r.p[1], yaw: r.yaw }, f.robot_radius,
            { alpha: 0.4 + 0.6 * r.conf, outline: true });
        }
        for (const b of det.balls) drawBall(b[0], b[1], b[2], f.ball_radius, { alpha: 0.4 + 0.6 * b[3], outline: true });
      }
    }
  }

  function frame() {
    draw();
    requestAnimationFrame(frame);
  }

  // --- messages from the viewer ---

  function setText(id, text) {
    const el = $(id);
    if (el.textContent !== text) el.textContent = text;
  }

  function say(text, error) {
    const el = $('message');
    el.textContent = text;
    el.classList.toggle('error', !!error);
  }

  function onState(s) {
    view.prev = view.cur; view.prevAt = view.curAt;
    view.cur = s; view.curAt = performance.now();
    setText('simtime', s.t.toFixed(2));
    setText('frame', String(s.frame));
    if (s.clock) {
      setText('rtf', s.clock.rtf.toFixed(2));
      setText('mode', s.clock.mode === 'scaled' ? `${s.clock.speed}×` : s.clock.mode);
      $('paused-badge').classList.toggle('hidden', !s.clock.paused);
      syncSpeed(s.clock);
    }
    updateOffField(s);
    // Without turf-sim's control reader the viewer refuses actions: say so. When turf-sim left, what the page
    // shows is its last word: say since when, and show no rate as if it were current.
    const live = !s.viewer || s.viewer.control;
    const gone = s.viewer && s.viewer.gone_since ? new Date(s.viewer.gone_since) : null;
    const badge = $('connection');
    if (view.recording) {
      setText('connection', 'recording');
      badge.classList.remove('warn');
    } else if (view.ws && view.ws.readyState === WebSocket.OPEN) {
      setText('connection', live ? 'live' : gone ? `turf-sim gone since ${gone.toLocaleTimeString()}` : 'view only');
      badge.classList.toggle('warn', !live);
      badge.title = live ? '' : gone ? 'turf-sim stopped: this is the last state it published'
        : 'turf-sim does not read the control topic yet: actions are refused';
    }
    view.simGone = !!gone;
    if (gone) {
      setText('rtf', '–');
      $('stats').classList.add('stale');
    } else {
      $('stats').classList.remove('stale');
    }
  }

  function syncSpeed(clock) {
    const sel = $('speed');
    if (document.activeElement === sel) return;
    const want = clock.mode === 'free' ? 'max' : clock.mode === 'realtime' ? '1'
      : clock.mode === 'scaled' ? String(clock.speed) : null;
    if (want && [...sel.options].some((o) => o.value === want) && sel.value !== want) sel.value = want;
  }

  function updateOffField(s) {
    const off = s.robots.filter((r) => !r.on).map((r) => `${r.team}:${r.id}`).join(',');
    const box = $('offfield');
    if (box.dataset.key === off) return;
    box.dataset.key = off;
    box.replaceChildren();
    if (!off) {
      const none = document.createElement('span');
      none.className = 'hint';
      none.textContent = 'none';
      box.append(none);
      return;
    }
    for (const r of s.robots.filter((q) => !q.on)) {
      const chip = document.createElement('button');
      chip.className = `chip ${r.team}`;
      chip.textContent = `${r.team === 'blue' ? 'B' : 'Y'}${r.id}`;
      chip.title = `put ${r.team} ${r.id} back on the field`;
      chip.addEventListener('click', () => putOn(r.team, r.id));
      box.append(chip);
    }
  }

  function onStats(st) {
    if (view.simGone) return;  // a late stats sample is not a current rate
    const body = $('stats').tBodies[0];
    body.replaceChildren();
    for (const s of st.streams) {
      const tr = document.createElement('tr');
      const cells = [s.name, `${s.rate.toFixed(0)}/s`, `${(100 * s.loss).toFixed(1)}%`,
        s.sent ? `${(1e3 * s.latency).toFixed(1)}±${(1e3 * s.jitter).toFixed(1)}` : '–'];
      for (const c of cells) {
        const td = document.createElement('td');
        td.textContent = c;
        tr.append(td);
      }
      body.append(tr);
    }
  }

  function onMessage(event) {
    let m;
    try { m = JSON.parse(event.data); } catch (e) { return; }
    view.received[m.type] = (view.received[m.type] || 0) + 1;
    switch (m.type) {
      case 'hello': say(`connected to prefix '${m.prefix}'`); break;
      case 'field': view.field = m; view.legged = null; view.cur = view.prev = null; setLegged(false); layout(); break;
      case 'legged': view.legged = m; view.field = null; view.cur = view.prev = null; setLegged(true); layout(); break;
      case 'state': onState(m); break;
      case 'stats': onStats(m); break;
      case 'reply':
        if (!m.ok) say(`turf-sim refused ${m.op} (${m.error}): ${m.reason}`, true);
        else if (!m.op.startsWith('teleport')) say(`${m.op}: ok at t=${m.t.toFixed(2)} s`);
        break;
      case 'refused': say(`viewer refused the request (${m.kind}): ${m.detail}`, true); break;
      default: break;
    }
  }

  // Legged scenes have neither off-field robots nor cameras: hide those controls.
  function setLegged(legged) {
    for (const el of document.querySelectorAll('.ssl-only')) el.classList.toggle('hidden', legged);
    for (const el of document.querySelectorAll('.legged-only')) el.classList.toggle('hidden', !legged);
  }

  function connect() {
    const scheme = location.protocol === 'https:' ? 'wss' : 'ws';
    const ws = new WebSocket(`${scheme}://${location.host}/ws`);
    view.ws = ws;
    ws.onopen = () => { $('connection').textContent = 'live'; $('connection').classList.remove('off'); };
    ws.onmessage = onMessage;
    ws.onclose = () => {
      $('connection').textContent = 'disconnected';
      $('connection').classList.add('off');
      setTimeout(connect, 1000);
    };
  }

  function send(message) {
    if (view.ws && view.ws.readyState === WebSocket.OPEN) view.ws.send(JSON.stringify(message));
  }

  // --- controls ---

  const round = (v) => Math.round(v * 1e4) / 1e4;

  function clampInside(x, y, r) {
    if (view.legged) {  // as page_request.h: kLeggedMargin beyond the lines, kLeggedArea without a field
      const lf = view.legged.field;
      const bx = (lf ? lf.length / 2 + 5 : 50) - r - 1e-3, by = (lf ? lf.width / 2 + 5 : 50) - r - 1e-3;
      return [Math.max(-bx, Math.min(bx, x)), Math.max(-by, Math.min(by, y))];
    }
    const f = view.field;
    const bx = f.length / 2 + f.boundary_goal - r - 1e-3, by = f.width / 2 + f.boundary - r - 1e-3;
    return [Math.max(-bx, Math.min(bx, x)), Math.max(-by, Math.min(by, y))];
  }

  function sendRobot(team, id, x, y, yaw) {
    send({ op: 'teleport_robot', team, id, on_field: true, x: round(x), y: round(y), yaw: round(yaw) });
  }

  function putOn(team, id) {
    const f = view.field;
    if (!f) return;
    const side = team === 'blue' ? -1 : 1;
    const x = side * Math.min(f.length / 2 - 0.3, 0.4 + 0.3 * id);
    sendRobot(team, id, x, -f.width / 2 + 0.25, side < 0 ? 0 : Math.PI);
  }

  function eventField(e) {
    const rect = canvas.getBoundingClientRect();
    return toField(e.clientX - rect.left, e.clientY - rect.top);
  }

  function robotAt(x, y) {
    if (view.legged) return null;  // legged robots: leggedAt
    const s = view.cur, f = view.field;
    if (!s || !f) return null;
    let best = null, bestD = f.robot_radius * 1.1;
    for (const r of s.robots) {
      if (!r.on) continue;
      const d = Math.hypot(r.p[0] - x, r.p[1] - y);
      if (d < bestD) { best = r; bestD = d; }
    }
    return best;
  }

  function ballAt(x, y) {
    const s = view.cur;
    if (!s || !s.ball || !sceneKnown()) return false;
    const reach = Math.max(ballRadius() * 2, 10 / view.scale);  // at least 10 px to grab
    return Math.hypot(s.ball.p[0] - x, s.ball.p[1] - y) < reach;
  }

  // The throw a drag aims, from where the ball is now (it may roll while the
  // user aims) towards the pointer; null for another drag or no ball.
  function throwOf(d, s) {
    if (!d || d.kind !== 'throw' || !s || !s.ball) return null;
    const [x, y] = clampInside(s.ball.p[0], s.ball.p[1], ballRadius());
    let vx = (d.x - x) * THROW_GAIN, vy = (d.y - y) * THROW_GAIN;
    const speed = Math.hypot(vx, vy);
    if (speed > MAX_THROW) { vx *= MAX_THROW / speed; vy *= MAX_THROW / speed; }
    return { x, y, vx, vy };
  }
  // Toward zero, so rounding never takes a clamped throw past MAX_THROW.
  const trunc = (v) => Math.trunc(v * 1e4) / 1e4;

  function sendThrow() {
    const t = throwOf(view.drag, view.cur);
    if (!t || Math.hypot(t.vx, t.vy) < 0.05) return;  // a click, not a throw
    send({ op: 'throw_ball', x: round(t.x), y: round(t.y), vx: trunc(t.vx), vy: trunc(t.vy) });
  }

  const leggedAt = (x, y) => (view.legged ? Legged.robotAt(view.leggedDrawn, x, y, LEGGED_REACH) : null);

  function sendDrag(final) {
    const d = view.drag;
    const now = performance.now();
    if (!final && now - d.lastSent < SEND_EVERY_MS) return;
    d.lastSent = now;
    if (d.kind === 'ball') send({ op: 'teleport_ball', x: round(d.x), y: round(d.y) });
    else if (d.kind === 'legged') {
      // Keep its orientation and height: only where it stands changes.
      send({ op: 'teleport_robot', robot: d.name, x: round(d.x), y: round(d.y), z: round(d.z),
        qw: round(d.q[0]), qx: round(d.q[1]), qy: round(d.q[2]), qz: round(d.q[3]) });
    } else sendRobot(d.team, d.id, d.x, d.y, d.yaw);
  }

  canvas.addEventListener('pointerdown', (e) => {
    if (!sceneKnown() || (view.field && view.mode === 'cameras')) return;
    const [x, y] = eventField(e);
    const legged = leggedAt(x, y);
    if (ballAt(x, y) && (e.button === 2 || e.shiftKey)) {
      view.drag = { kind: 'throw', x, y };
    } else if (ballAt(x, y)) {
      view.drag = { kind: 'ball', x, y, lastSent: 0 };
    } else if (legged) {
      const [rx, ry, rz] = legged.root;
      view.drag = { kind: 'legged', name: legged.name, root: [rx, ry], x: rx, y: ry, z: Math.max(0, rz), q: legged.q,
        dx: rx - x, dy: ry - y, lastSent: 0 };
    } else {
      const r = robotAt(x, y);
      if (!r) return;
      const rotate = e.shiftKey || e.button === 2;
      view.drag = { kind: 'robot', team: r.team, id: r.id, x: r.p[0], y: r.p[1], yaw: r.yaw, rotate, lastSent: 0,
        dx: r.p[0] - x, dy: r.p[1] - y };
    }
    canvas.setPointerCapture(e.pointerId);
    e.preventDefault();
  });

  canvas.addEventListener('pointermove', (e) => {
    const d = view.drag;
    if (!d) {
      const [x, y] = sceneKnown() ? eventField(e) : [0, 0];
      const ball = sceneKnown() && ballAt(x, y);
      canvas.style.cursor = ball || (sceneKnown() && (robotAt(x, y) || leggedAt(x, y))) ? 'grab' : 'default';
      canvas.title = ball ? 'drag to move the ball; right-drag or shift-drag to throw it' : '';
      return;
    }
    canvas.style.cursor = d.kind === 'throw' ? 'crosshair' : 'grabbing';
    const [x, y] = eventField(e);
    const f = view.field;
    if (d.kind === 'throw') {  // nothing is sent until the release
      [d.x, d.y] = [x, y];
      return;
    }
    if (d.kind === 'legged') {
      [d.x, d.y] = clampInside(x + d.dx, y + d.dy, 0);
    } else if (d.kind === 'ball' && view.legged) {
      [d.x, d.y] = clampInside(x, y, ballRadius());
    } else if (d.kind === 'robot' && d.rotate) {
      d.yaw = Math.atan2(y - d.y, x - d.x);
    } else if (d.kind === 'robot') {
      [d.x, d.y] = clampInside(x + d.dx, y + d.dy, f.robot_radius);
    } else {
      [d.x, d.y] = clampInside(x, y, f.ball_radius);
    }
    sendDrag(false);
  });

  const endDrag = (e) => {
    if (!view.drag) return;
    if (view.drag.kind === 'throw') {
      if (e.type === 'pointerup') sendThrow();
    } else {
      sendDrag(true);
    }
    view.drag = null;
  };
  canvas.addEventListener('pointerup', endDrag);
  canvas.addEventListener('pointercancel', endDrag);
  canvas.addEventListener('lostpointercapture', endDrag);  // e.g. the window lost focus: no throw
  canvas.addEventListener('contextmenu', (e) => e.preventDefault());

  canvas.addEventListener('dblclick', (e) => {
    if (!view.field) return;
    const r = robotAt(...eventField(e));
    if (r) send({ op: 'teleport_robot', team: r.team, id: r.id, on_field: false });
  });

  canvas.addEventListener('wheel', (e) => {
    if (!view.field) return;
    const r = robotAt(...eventField(e));
    if (!r) return;
    e.preventDefault();
    sendRobot(r.team, r.id, r.p[0], r.p[1], r.yaw + (e.deltaY < 0 ? 1 : -1) * Math.PI / 12);
  }, { passive: false });

  $('pause').addEventListener('click', () => send({ op: 'pause' }));
  $('resume').addEventListener('click', () => send({ op: 'resume' }));
  $('reset').addEventListener('click', () => send({ op: 'reset' }));
  $('step').addEventListener('click', () => {
    const n = Math.max(1, Math.min(1000, Math.round(Number($('step-count').value) || 1)));
    send({ op: 'step', count: n });
  });
  $('speed').addEventListener('change', (e) => {
    const v = e.target.value;
    if (v === 'max') send({ op: 'time_mode', mode: 'free' });
    else if (v === '1') send({ op: 'time_mode', mode: 'realtime' });
    else send({ op: 'time_mode', mode: 'scaled', speed: Number(v) });
  });
  $('realism').addEventListener('change', (e) => {
    if (e.target.value) send({ op: 'realism', preset: e.target.value });
  });
  function setMode(mode) {
    const buttons = [...$('view').querySelectorAll('button')];
    if (!buttons.some((b) => b.dataset.view === mode)) return;
    view.mode = mode;
    for (const b of buttons) b.classList.toggle('active', b.dataset.view === mode);
  }
  for (const b of $('view').querySelectorAll('button')) b.addEventListener('click', () => setMode(b.dataset.view));
  // A bookmarkable start view: #view=cameras (or truth, both).
  const hashView = /(?:^#|&)view=(\w+)/.exec(location.hash);
  if (hashView) setMode(hashView[1]);
  document.addEventListener('keydown', (e) => {
    if (e.key !== ' ' || e.target.tagName === 'INPUT' || e.target.tagName === 'SELECT') return;
    e.preventDefault();
    send({ op: view.cur && view.cur.clock && view.cur.clock.paused ? 'resume' : 'pause' });
  });
  window.addEventListener('resize', layout);

  // For tests and the console: where a field point is drawn, and what is there.
  window.turfViewer = {
    // The field and a state have arrived, are drawn, and the controls are live.
    ready: () => !!(sceneKnown() && view.cur && view.drawn && view.cur.viewer && view.cur.viewer.control &&
      view.ws && view.ws.readyState === WebSocket.OPEN),
    state: () => view.cur,
    // recording.js: a message fetched over HTTP, handled as if the WebSocket had brought it.
    deliver: (text) => onMessage({ data: text }),
    setRecording: (on) => { view.recording = on; },
    received: () => ({ ...view.received, socket: view.ws ? view.ws.readyState : -1 }),
    field: () => view.field,
    legged: () => view.legged,
    // Legged robots as drawn: root body position (m), the drawn centre of its
    // first shape (the root's, e.g. the Nao's torso) and how many shapes.
    leggedDrawn: () => view.leggedDrawn.map((r) => ({ name: r.name, id: r.id, root: r.root,
      first: r.shapes.length ? Legged.centre(r.shapes[0]) : null, shapes: r.shapes.length })),
    fieldToClient: (x, y) => {
      const rect = canvas.getBoundingClientRect();
      const [cx, cy] = toCanvas(x, y);
      return { x: rect.left + cx, y: rect.top + cy };
    },
    colorAt: (x, y) => {
      const [cx, cy] = toCanvas(x, y);
      return Array.from(ctx.getImageData(Math.round(cx * view.dpr), Math.round(cy * view.dpr), 1, 1).data);
    },
  };

  layout();
  connect();
  requestAnimationFrame(frame);
})();
