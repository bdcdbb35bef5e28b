// turf-viewer --recording: a time slider, play/pause and speed over a recorded match
// (participants/viewer/recording_viewer.h). The page asks the viewer for the world at a simulation time,
// GET /recording/state?t=S, and hands the answer to app.js as if it had come over the WebSocket; live
// viewers answer /recording/info with 404, and then this file does nothing.
'use strict';

(() => {
  const $ = (id) => document.getElementById(id);
  const FETCH_EVERY_MS = 33;  // while playing: ~30 states a second, one request at a time
  const STATS_EVERY_S = 1;    // of simulation time
  const rec = { start: 0, end: 0, t: 0, playing: false, speed: 1, inFlight: false, wanted: null,
    lastTick: 0, lastFetch: 0, statsT: -Infinity };

  async function getJson(target) {
    const r = await fetch(target, { cache: 'no-store' });
    return r.ok ? r.json() : null;
  }

  // One request at a time; the newest wanted time wins.
  async function show(t) {
    rec.wanted = t;
    if (rec.inFlight) return;
    rec.inFlight = true;
    while (rec.wanted !== null) {
      const want = rec.wanted;
      rec.wanted = null;
      try {
        const s = await getJson(`/recording/state?t=${want.toFixed(6)}`);
        if (s) window.turfViewer.deliver(JSON.stringify(s));
        if (Math.abs(want - rec.statsT) >= STATS_EVERY_S) {
          rec.statsT = want;
          const st = await getJson(`/recording/stats?t=${want.toFixed(6)}`);
          if (st) window.turfViewer.deliver(JSON.stringify(st));
        }
      } catch (e) { /* the viewer is gone; app.js shows the closed socket */ }
    }
    rec.inFlight = false;
  }

  function setTime(t) {
    rec.t = Math.min(rec.end, Math.max(rec.start, t));
    $('rec-slider').value = String(rec.t);
    $('rec-time').textContent = `${rec.t.toFixed(2)} / ${rec.end.toFixed(2)} s`;
  }

  // Stopping (Pause, or the end reached) shows the state of the time where it stopped: while playing, states are
  // fetched only every FETCH_EVERY_MS, so the last one fetched may be a frame before it.
  function setPlaying(on) {
    if (on && rec.t >= rec.end) setTime(rec.start);
    rec.playing = on;
    $('rec-play').textContent = on ? 'Pause' : 'Play';
    if (!on) show(rec.t);
  }

  function tick(now) {
    if (rec.playing) {
      setTime(rec.t + ((now - rec.lastTick) / 1000) * rec.speed);
      if (rec.t >= rec.end) {
        setPlaying(false);  // shows the end
      } else if (now - rec.lastFetch >= FETCH_EVERY_MS) {
        rec.lastFetch = now;
        show(rec.t);
      }
    }
    rec.lastTick = now;
    requestAnimationFrame(tick);
  }

  async function start() {
    let info = null;
    try { info = await getJson('/recording/info'); } catch (e) { return; }
    if (!info || info.type !== 'recording') return;  // a live viewer
    window.turfViewer.setRecording(true);
    for (const el of document.querySelectorAll('.live-only')) el.classList.add('hidden');
    $('recording-bar').classList.remove('hidden');
    $('rec-file').textContent = info.file;
    if (info.damage) {
      $('rec-damage').textContent = `damaged file, shown up to the damage: ${info.damage}`;
      $('rec-damage').classList.remove('hidden');
    }
    if (info.start === undefined) {
      $('rec-time').textContent = 'nothing to show';
      return;
    }
    rec.start = info.start;
    rec.end = info.end;
    const slider = $('rec-slider');
    slider.min = String(rec.start);
    slider.max = String(rec.end);
    slider.step = '0.01';
    slider.addEventListener('input', () => { setTime(Number(slider.value)); show(rec.t); });
    $('rec-play').addEventListener('click', () => setPlaying(!rec.playing));
    $('rec-speed').addEventListener('change', () => { rec.speed = Number($('rec-speed').value); });
    document.addEventListener('keydown', (e) => {
      if (e.key !== ' ' || e.target.tagName === 'INPUT' || e.target.tagName === 'SELECT') return;
      e.preventDefault();
      e.stopPropagation();  // app.js's space would ask a simulator to pause
      setPlaying(!rec.playing);
    }, true);
    setTime(rec.start);
    show(rec.t);
    requestAnimationFrame((now) => { rec.lastTick = now; tick(now); });
  }

  // For tests and the console.
  window.turfRecording = { time: () => rec.t, playing: () => rec.playing, seek: (t) => { setTime(t); show(rec.t); } };
  start();
})();
