// turf-viewer's legged view: the 3D soccer field (or a ground grid) from above
// and each robot as the top-down projection of its shapes, from the "legged"
// message and the states' "links" (participants/viewer/legged_json.h).
// Pure geometry and drawing; app.js owns the canvas, the socket and the input.
'use strict';

window.turfLegged = (() => {
  // RoboCup 3D field markings that the scene info does not carry
  // (shared/protocols/simspark.md): centre circle, penalty areas.
  const CENTER_RADIUS = 2.0;
  const PENALTY_DEPTH = 1.8;
  const PENALTY_WIDTH = 6.0;
  const BORDER = 1.0;  // m of ground shown around the field lines
  const ROBOT_MARGIN = 0.6;  // m shown around every robot, e.g. parked beside the field
  const ARC = 16;  // points per sampled circle

  // --- quaternions (w, x, y, z) and rotations ---

  function matrix(q) {
    const [w, x, y, z] = q;
    return [
      1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y),
    ];
  }
  const rotate = (m, v) => [
    m[0] * v[0] + m[1] * v[1] + m[2] * v[2],
    m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
    m[6] * v[0] + m[7] * v[1] + m[8] * v[2],
  ];
  function multiply(a, b) {
    const [aw, ax, ay, az] = a, [bw, bx, by, bz] = b;
    return [aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
      aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw];
  }

  // Andrew's monotone chain: the convex hull of 2D points, counter-clockwise.
  function hull(points) {
    const p = points.slice().sort((a, b) => a[0] - b[0] || a[1] - b[1]);
    if (p.length < 3) return p;
    const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    const lower = [], upper = [];
    for (const q of p) {
      while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], q) <= 0) lower.pop();
      lower.push(q);
    }
    for (let i = p.length - 1; i >= 0; --i) {
      const q = p[i];
      while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], q) <= 0) upper.pop();
      upper.push(q);
    }
    return lower.slice(0, -1).concat(upper.slice(0, -1));
  }

  // --- one shape's outline seen from above ---

  // Points of the shape's surface (world frame) whose projections' hull is
  // its outline; `c` centre, `m` rotation world <- geom, `s` MuJoCo size.
  function surfacePoints(shape, c, m, s) {
    const at = (v) => { const r = rotate(m, v); return [c[0] + r[0], c[1] + r[1], c[2] + r[2]]; };
    const pts = [];
    if (shape === 'box') {
      for (const sx of [-1, 1]) for (const sy of [-1, 1]) for (const sz of [-1, 1]) pts.push(at([sx * s[0], sy * s[1], sz * s[2]]));
    } else if (shape === 'cylinder') {
      for (let i = 0; i < ARC; ++i) {
        const a = 2 * Math.PI * i / ARC;
        for (const sz of [-1, 1]) pts.push(at([s[0] * Math.cos(a), s[0] * Math.sin(a), sz * s[1]]));
      }
    } else if (shape === 'ellipsoid') {
      for (let j = -3; j <= 3; ++j) {
        const phi = j * Math.PI / 6;
        for (let i = 0; i < ARC; ++i) {
          const a = 2 * Math.PI * i / ARC;
          pts.push(at([s[0] * Math.cos(a) * Math.cos(phi), s[1] * Math.sin(a) * Math.cos(phi), s[2] * Math.sin(phi)]));
        }
      }
    }
    return pts;
  }

  // {kind: 'circle', c, r} or {kind: 'poly', pts}, with `top` (highest z) to
  // draw lower parts first; null for a shape it cannot draw.
  function outline(geom, c, q) {
    const s = geom.size;
    if (geom.shape === 'sphere') return { kind: 'circle', c, r: s[0], top: c[2] + s[0] };
    const m = matrix(q);
    if (geom.shape === 'capsule') {  // the hull of its two end spheres' circles
      const axis = rotate(m, [0, 0, s[1]]);
      const pts = [];
      for (const sign of [-1, 1]) {
        const e = [c[0] + sign * axis[0], c[1] + sign * axis[1]];
        for (let i = 0; i < ARC; ++i) {
          const a = 2 * Math.PI * i / ARC;
          pts.push([e[0] + s[0] * Math.cos(a), e[1] + s[0] * Math.sin(a)]);
        }
      }
      return { kind: 'poly', pts: hull(pts), top: c[2] + Math.abs(axis[2]) + s[0] };
    }
    const surface = surfacePoints(geom.shape, c, m, s);
    if (!surface.length) return null;
    return { kind: 'poly', pts: hull(surface.map((p) => [p[0], p[1]])), top: Math.max(...surface.map((p) => p[2])) };
  }

  // --- robots ---

  // Every robot with poses: its name, id, root body pose and its shapes'
  // outlines in world metres. `moved`: {name: [dx, dy]} shifts a robot being dragged.
  function robots(scene, links, moved) {
    const out = [];
    if (!scene || !links) return out;
    for (const robot of scene.robots) {
      const flat = links[robot.name];
      if (!flat || flat.length !== 7 * robot.bodies.length || !robot.bodies.length) continue;
      const [dx, dy] = (moved && moved[robot.name]) || [0, 0];
      const pose = (b) => ({ p: [flat[7 * b] + dx, flat[7 * b + 1] + dy, flat[7 * b + 2]], q: flat.slice(7 * b + 3, 7 * b + 7) });
      const shapes = [];
      for (const g of robot.geoms) {
        const body = pose(g.b);
        const r = rotate(matrix(body.q), g.p);
        const o = outline(g, [body.p[0] + r[0], body.p[1] + r[1], body.p[2] + r[2]], multiply(body.q, g.q));
        if (o) shapes.push(o);
      }
      const root = pose(0);
      out.push({ name: robot.name, id: robot.id, root: root.p, q: root.q, shapes });
    }
    return out;
  }

  // The robot whose outline (or root, within `reach` m) is at (x, y), or null.
  function robotAt(drawn, x, y, reach) {
    let best = null, bestD = reach;
    for (const r of drawn) {
      const d = Math.hypot(r.root[0] - x, r.root[1] - y);
      const inside = r.shapes.some((s) => (s.kind === 'circle' ? Math.hypot(s.c[0] - x, s.c[1] - y) <= s.r : contains(s.pts, x, y)));
      const score = inside ? Math.min(d, reach * 0.5) : d;
      if (score < bestD) { best = r; bestD = score; }
    }
    return best;
  }
  function contains(pts, x, y) {
    let inside = false;
    for (let i = 0, j = pts.length - 1; i < pts.length; j = i++) {
      const [xi, yi] = pts[i], [xj, yj] = pts[j];
      if ((yi > y) !== (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi) inside = !inside;
    }
    return inside;
  }

  // --- view ---

  // Half extents (m) to show: the field and a border, grown to every robot.
  function extents(scene, drawn) {
    let hx = 3, hy = 3;
    if (scene && scene.field) {
      hx = scene.field.length / 2 + scene.field.goal_depth + BORDER;
      hy = scene.field.width / 2 + BORDER;
    }
    for (const r of drawn) {
      hx = Math.max(hx, Math.abs(r.root[0]) + ROBOT_MARGIN);
      hy = Math.max(hy, Math.abs(r.root[1]) + ROBOT_MARGIN);
    }
    return { hx, hy };
  }

  // T: {ctx, toCanvas(x, y) -> [cx, cy], px(m) -> pixels, width, height (CSS px), toField}
  function drawGround(T, scene) {
    const { ctx } = T;
    const f = scene.field;
    if (!f) { drawGrid(T); return; }
    ctx.fillStyle = '#1d6b35';  // no walls: the grass goes on (robots park beside the field)
    ctx.fillRect(0, 0, T.width, T.height);
    const L = f.length / 2, W = f.width / 2;
    ctx.strokeStyle = 'rgba(255,255,255,0.92)';
    ctx.lineWidth = Math.max(1, T.px(0.05));
    const rect = (x0, y0, x1, y1) => {
      const [a, b] = T.toCanvas(Math.min(x0, x1), Math.max(y0, y1));
      ctx.strokeRect(a, b, T.px(Math.abs(x1 - x0)), T.px(Math.abs(y1 - y0)));
    };
    rect(-L, -W, L, W);
    const [t0, t1] = [T.toCanvas(0, W), T.toCanvas(0, -W)];
    ctx.beginPath(); ctx.moveTo(...t0); ctx.lineTo(...t1); ctx.stroke();
    const [cx, cy] = T.toCanvas(0, 0);
    ctx.beginPath(); ctx.arc(cx, cy, T.px(CENTER_RADIUS), 0, 2 * Math.PI); ctx.stroke();
    ctx.beginPath(); ctx.arc(cx, cy, Math.max(1.5, T.px(0.05)), 0, 2 * Math.PI); ctx.fillStyle = '#ffffff'; ctx.fill();
    for (const side of [-1, 1]) {
      rect(side * L, -PENALTY_WIDTH / 2, side * (L - PENALTY_DEPTH), PENALTY_WIDTH / 2);
      ctx.save();
      ctx.strokeStyle = side < 0 ? '#f2d21b' : '#2f6fed';  // goal colours as SimSpark's monitor: left yellow, right blue
      ctx.lineWidth = Math.max(2, T.px(0.1));
      const g = f.goal_width / 2, back = side * (L + f.goal_depth);
      const p = [T.toCanvas(side * L, g), T.toCanvas(back, g), T.toCanvas(back, -g), T.toCanvas(side * L, -g)];
      ctx.beginPath(); ctx.moveTo(...p[0]); ctx.lineTo(...p[1]); ctx.lineTo(...p[2]); ctx.lineTo(...p[3]);
      ctx.stroke();
      ctx.restore();
    }
  }

  // No field: a 1 m grid (every 5th line brighter) and the axes.
  function drawGrid(T) {
    const { ctx } = T;
    ctx.fillStyle = '#2a3a2e';
    ctx.fillRect(0, 0, T.width, T.height);
    const [x0, y1] = T.toField(0, 0), [x1, y0] = T.toField(T.width, T.height);
    ctx.lineWidth = 1;
    for (let x = Math.ceil(x0); x <= x1; ++x) {
      ctx.strokeStyle = x === 0 ? 'rgba(255,120,120,0.8)' : x % 5 === 0 ? 'rgba(255,255,255,0.35)' : 'rgba(255,255,255,0.12)';
      const [a] = T.toCanvas(x, 0);
      ctx.beginPath(); ctx.moveTo(a, 0); ctx.lineTo(a, T.height); ctx.stroke();
    }
    for (let y = Math.ceil(y0); y <= y1; ++y) {
      ctx.strokeStyle = y === 0 ? 'rgba(120,255,120,0.8)' : y % 5 === 0 ? 'rgba(255,255,255,0.35)' : 'rgba(255,255,255,0.12)';
      const [, b] = T.toCanvas(0, y);
      ctx.beginPath(); ctx.moveTo(0, b); ctx.lineTo(T.width, b); ctx.stroke();
    }
  }

  // Every robot's shapes, lowest first across all robots (so a head is on top
  // of its shoulders, and a standing robot on top of a fallen one), shaded by
  // height, then the labels.
  function drawRobots(T, drawn, style) {
    const { ctx } = T;
    const all = [];
    for (const r of drawn) for (const s of r.shapes) all.push(s);
    all.sort((a, b) => a.top - b.top);
    ctx.save();
    ctx.globalAlpha = style.alpha;
    ctx.lineWidth = 1;
    ctx.strokeStyle = '#20242a';
    for (const s of all) {
      const light = Math.round(150 + 95 * Math.max(0, Math.min(1, s.top / 0.6)));
      ctx.fillStyle = `rgb(${light},${light},${Math.min(255, light + 10)})`;
      ctx.beginPath();
      if (s.kind === 'circle') {
        const [cx, cy] = T.toCanvas(s.c[0], s.c[1]);
        ctx.arc(cx, cy, Math.max(0.75, T.px(s.r)), 0, 2 * Math.PI);
      } else {
        s.pts.forEach((p, i) => { const [cx, cy] = T.toCanvas(p[0], p[1]); if (i) ctx.lineTo(cx, cy); else ctx.moveTo(cx, cy); });
        ctx.closePath();
      }
      ctx.fill();
      ctx.stroke();
    }
    ctx.font = 'bold 11px "DejaVu Sans", sans-serif';
    ctx.textAlign = 'center';
    ctx.textBaseline = 'bottom';
    // Names, or ids where two robots stand too close for their names.
    const widest = Math.max(0, ...drawn.map((r) => ctx.measureText(r.name).width)) + 8;
    let names = true;
    for (let i = 0; i < drawn.length && names; ++i) {
      for (let j = i + 1; j < drawn.length && names; ++j) {
        const dx = T.px(Math.abs(drawn[i].root[0] - drawn[j].root[0]));
        const dy = T.px(Math.abs(drawn[i].root[1] - drawn[j].root[1]));
        names = dx >= widest || dy >= 16;
      }
    }
    for (const r of drawn) {
      const [cx, cy] = T.toCanvas(r.root[0], r.root[1]);
      const label = names ? r.name : String(r.id);
      const w = ctx.measureText(label).width + 6;
      const y = cy - Math.max(10, T.px(0.35));
      ctx.fillStyle = 'rgba(0,0,0,0.55)';
      ctx.fillRect(cx - w / 2, y - 13, w, 14);
      ctx.fillStyle = style.highlight === r.name ? '#ffd54f' : '#ffffff';
      ctx.fillText(label, cx, y);
    }
    ctx.restore();
  }

  // A shape's drawn centre (world metres): for tests and the console.
  function centre(s) {
    if (s.kind === 'circle') return [s.c[0], s.c[1]];
    const n = s.pts.length;
    return [s.pts.reduce((a, p) => a + p[0], 0) / n, s.pts.reduce((a, p) => a + p[1], 0) / n];
  }

  return { robots, robotAt, extents, drawGround, drawRobots, centre, hull, matrix };
})();
