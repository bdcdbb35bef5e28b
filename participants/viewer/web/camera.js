// The camera panel: the newest image of one robot camera, polled from the viewer (GET /camera/<robot>/<camera>.jpg,
// participants/viewer/camera_frames.h). Two <img> take turns: the next frame loads into the hidden one and is shown
// when it has come, so a missing frame never blanks the panel. Opens at ?camera=<robot>/<camera> too.
'use strict';

(() => {
  const input = document.getElementById('camera-id');
  const status = document.getElementById('camera-status');
  const images = [document.getElementById('camera-a'), document.getElementById('camera-b')];
  const kId = /^[A-Za-z0-9_]{1,64}\/[A-Za-z0-9_]{1,64}$/;
  let id = null;
  let loading = 0;  // which <img> loads the next frame
  let frames = 0;
  let timer = null;
  let generation = 0;  // a new camera ignores the old one's answers

  function poll() {
    if (!id) return;
    const g = generation;
    const next = images[loading];
    next.onload = () => {
      if (g !== generation) return;
      next.classList.remove('hidden');
      images[1 - loading].classList.add('hidden');
      loading = 1 - loading;
      frames += 1;
      status.textContent = `${id}: ${frames} frames`;
      timer = setTimeout(poll, 100);
    };
    next.onerror = () => {
      if (g !== generation) return;
      if (frames === 0) status.textContent = `${id}: no image yet (is the camera on in turf-render?)`;
      timer = setTimeout(poll, 500);
    };
    next.src = `/camera/${id}.jpg?n=${Date.now()}`;
  }

  function show(value) {
    const v = value.trim();
    clearTimeout(timer);
    generation += 1;
    frames = 0;
    for (const img of images) img.classList.add('hidden');
    if (!kId.test(v)) {
      id = null;
      status.textContent = v ? 'a camera is robot/camera, e.g. red_1/camera' : 'none';
      return;
    }
    id = v;
    status.textContent = `${id}: waiting`;
    poll();
  }

  document.getElementById('camera-show').addEventListener('click', () => show(input.value));
  input.addEventListener('keydown', (e) => { if (e.key === 'Enter') show(input.value); });
  const asked = new URLSearchParams(location.search).get('camera');
  if (asked) {
    input.value = asked;
    show(asked);
  }
})();
