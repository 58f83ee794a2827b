// vascsim replay: the browser half of `vascsim replay` (docs/replay.md).
//
// The map pixels come from the server's renderer (/api/frame.png); this script draws only the
// interaction: timeline, plots, hover readout, dialogs. Plain ES2020, no build step, nothing
// fetched but the server's own API. Every request carries the token.
(() => {
  'use strict';

  // ------------------------------------------------------------------ basics
  const $ = (id) => document.getElementById(id);
  const TOKEN = (() => {
    const q = new URLSearchParams(location.search).get('token');
    if (q) return q;
    const meta = document.querySelector('meta[name="vascsim-token"]');
    const m = meta ? meta.getAttribute('content') : '';
    return m && !m.includes('{{') ? m : '';
  })();
  const CSS_ZOOM_STEP = 1.25;
  const HOVER_RADIUS_PX = 15;
  const PLAY_FRAME_MS = 1000 / 30;

  // Query strings keep commas readable (layers=walls,rod; center=0.4,0.5).
  const enc = (v) => encodeURIComponent(String(v)).replace(/%2C/gi, ',');
  function apiUrl(path, params) {
    const parts = [];
    for (const [k, v] of Object.entries(params || {})) if (v !== undefined && v !== null) parts.push(`${k}=${enc(v)}`);
    if (TOKEN) parts.push(`token=${enc(TOKEN)}`);
    return parts.length ? `${path}?${parts.join('&')}` : path;
  }
  function absUrl(u) { return new URL(u, location.href).href; }

  class ApiError extends Error {
    constructor(status, message, parameter) { super(message); this.status = status; this.parameter = parameter; }
  }
  async function errorFrom(resp, what) {
    let msg = `${resp.status} ${resp.statusText}`, param;
    try {
      const text = await resp.text();
      try {
        const j = JSON.parse(text);
        if (j && j.error) { msg = j.error; param = j.parameter; }
      } catch (_) { if (text) msg = text.slice(0, 200); }
    } catch (_) { /* keep the status */ }
    return new ApiError(resp.status, `${what}: ${msg}${param ? ` (parameter ${param})` : ''} [HTTP ${resp.status}]`, param);
  }
  async function getJSON(path, params, init) {
    const url = apiUrl(path, params);
    let resp;
    try { resp = await fetch(url, Object.assign({ cache: 'no-store' }, init || {})); } catch (e) {
      throw new ApiError(0, `${path}: the server does not answer (${e.message})`);
    }
    if (!resp.ok) throw await errorFrom(resp, path);
    return resp.json();
  }

  // ------------------------------------------------------------------ status line
  let statusTimer = null;
  function showStatus(text, isError) {
    const el = $('status-line');
    el.textContent = text;
    el.classList.toggle('error', !!isError);
    el.title = isError ? 'click to dismiss' : '';
    clearTimeout(statusTimer);
    if (!isError && text) statusTimer = setTimeout(() => { el.textContent = ''; }, 4000);
  }
  function showError(e) {
    const msg = e instanceof Error ? e.message : String(e);
    console.warn('vascsim replay:', msg);  // a warning, not an error: the page stays usable
    showStatus(msg, true);
  }

  // ------------------------------------------------------------------ formatting
  const fmtTime = (t) => `${t.toFixed(3)} s`;
  function trimNum(s) { return s.includes('.') ? s.replace(/0+$/, '').replace(/\.$/, '') : s; }
  const fmtParamT = (t) => trimNum(t.toFixed(9));
  const fmtZoom = (z) => String(Number(z.toPrecision(6)));
  const fmtCoord = (x) => trimNum(x.toFixed(6));
  function fmtSig(v, n) {
    if (v === null || v === undefined || !isFinite(v)) return '–';
    if (v === 0) return '0';
    const d = Math.min(6, Math.max(0, n - 1 - Math.floor(Math.log10(Math.abs(v)))));
    return v.toFixed(d);
  }
  // mN in at most 8 characters: 4 significant digits, exponent for tiny values.
  function fmtForce(v) {
    if (!isFinite(v)) return '–';
    if (v === 0) return '0';
    const a = Math.abs(v);
    if (a < 1e-3) return v.toExponential(2);
    return fmtSig(v, 4);
  }
  const esc = (s) => String(s).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' }[c]));
  function shellQuote(s) { return /^[\w@%+=:,./-]+$/.test(s) ? s : `'${s.replace(/'/g, `'\\''`)}'`; }

  // Display units: metres as mm, newtons as mN (µ when tiny), speeds as mm/s.
  function displayUnit(unit, maxAbs) {
    const tiny = (limit) => maxAbs > 0 && maxAbs < limit;
    switch (unit) {
      case 'm': return tiny(1e-4) ? { unit: 'µm', f: 1e6 } : { unit: 'mm', f: 1e3 };
      case 'm/s': return tiny(1e-4) ? { unit: 'µm/s', f: 1e6 } : { unit: 'mm/s', f: 1e3 };
      case 'N': return tiny(1e-5) ? { unit: 'µN', f: 1e6 } : { unit: 'mN', f: 1e3 };
      default: return { unit: unit || '', f: 1 };
    }
  }
  function niceStep(range, count) {
    if (!(range > 0)) return 1;
    const raw = range / Math.max(1, count);
    const p = Math.pow(10, Math.floor(Math.log10(raw)));
    const m = raw / p;
    return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * p;
  }
  function ticks(lo, hi, count) {
    const step = niceStep(hi - lo, count);
    const out = [];
    for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
    return { step, values: out };
  }
  const decimalsFor = (step) => Math.max(0, Math.min(6, -Math.floor(Math.log10(step) + 1e-9)));

  // ------------------------------------------------------------------ state
  const S = {
    info: { a: null, b: null },
    compare: false,
    t: 0, t0: 0, t1: 0, dt: 0.01,
    playing: false, speed: 1,
    camera: 'fit', zoom: 1, center: null,
    layers: [],
    compareMode: 'side',
    size: { w: 1280, h: 720, dpr: 1 },
    anchor: null,   // {w: [x, y], p: [px, py], key}: a world point that must stay under a pixel (zoom/pan)
    exportTouched: false,
    started: false,     // frames are requested once the page knows its size and the link's view
  };
  const centreCache = new Map();   // size+panel key -> {p: [px, py], exact}: pixel of the camera centre

  function runs() { return S.compare ? ['a', 'b'] : ['a']; }
  function panelKey(layers) { return layers.includes('hud') || layers.includes('legend') ? 'panel' : 'bare'; }
  function viewKey(w, h, layers) { return `${w}x${h}|${panelKey(layers)}`; }

  function viewParams() {
    const p = { width: S.size.w, height: S.size.h, camera: S.camera, zoom: fmtZoom(S.zoom) };
    if (S.camera === 'center' && S.center) p.center = `${fmtCoord(S.center[0])},${fmtCoord(S.center[1])}`;
    p.layers = S.layers.join(',');
    return p;
  }
  function frameParams(run) {
    const p = Object.assign({ t: fmtParamT(S.t) }, viewParams());
    if (run === 'a' && S.compare && S.compareMode === 'overlay') p.overlay = 'b';
    p.run = run;
    return p;
  }
  function frameUrl(run) { return apiUrl('/api/frame.png', frameParams(run)); }

  // ------------------------------------------------------------------ map slots
  // One per shown map. At most one request in flight; when it returns and the wanted view
  // changed meanwhile, the newest is requested; replies older than the shown one are dropped.
  class Slot {
    constructor(run) {
      this.run = run;
      this.box = $(`map-${run}`);
      this.img = $(`frame-${run}`);
      this.overlay = $(`overlay-${run}`);
      this.spinner = $(`spinner-${run}`);
      this.seq = 0;
      this.shownSeq = 0;
      this.inFlight = null;
      this.shownUrl = null;
      this.shownParams = null;
      this.failedUrl = null;
      this.blob = null;
      this.blobUrl = null;
      this.view = null;
      this.lastStart = 0;
      this.timer = null;
    }
    active() { return this.run === 'a' || (S.compare && S.compareMode === 'side'); }
    wantedUrl() { return frameUrl(this.run); }
    settled() {
      if (!this.active()) return true;
      const want = this.wantedUrl();
      return !this.inFlight && !this.timer && (want === this.shownUrl || want === this.failedUrl);
    }
    update() {
      if (!this.active()) return;
      this.applyPreview();
      if (this.inFlight || this.timer) return;
      const url = this.wantedUrl();
      if (url === this.shownUrl || url === this.failedUrl) return;
      const wait = S.playing ? PLAY_FRAME_MS - (performance.now() - this.lastStart) : 0;
      if (wait > 1) {
        this.timer = setTimeout(() => { this.timer = null; this.update(); checkReady(); }, wait);
        return;
      }
      this.request(url, frameParams(this.run));
    }
    // Asks for the wanted frame again, though it is the one shown: what the server draws for it
    // changed (the run ended, and the HUD says how).
    refetch() {
      this.shownUrl = null;
      this.failedUrl = null;
      this.update();
    }
    async request(url, params) {
      const seq = ++this.seq;
      this.inFlight = { url, seq };
      this.lastStart = performance.now();
      const spin = setTimeout(() => { this.spinner.hidden = false; }, 250);
      try {
        const resp = await fetch(url, { cache: 'no-store' });
        if (!resp.ok) throw await errorFrom(resp, '/api/frame.png');
        const header = resp.headers.get('X-Vascsim-View');
        const blob = await resp.blob();
        if (seq <= this.shownSeq) return;  // stale: a newer frame is already shown
        let view = null;
        if (header) {
          try { view = JSON.parse(header); } catch (_) { showError('/api/frame.png: unreadable X-Vascsim-View header'); }
        } else {
          showError('/api/frame.png: no X-Vascsim-View header (hover and wheel zoom need it)');
        }
        const objectUrl = URL.createObjectURL(blob);
        const img = new Image();
        img.src = objectUrl;
        try { await img.decode(); } catch (_) {
          URL.revokeObjectURL(objectUrl);
          throw new Error('/api/frame.png: the reply is not an image');
        }
        this.img.src = objectUrl;
        try { await this.img.decode(); } catch (_) { /* already decoded above */ }
        if (this.blobUrl) URL.revokeObjectURL(this.blobUrl);
        this.blobUrl = objectUrl;
        this.blob = blob;
        this.shownSeq = seq;
        this.shownUrl = url;
        this.shownParams = params;
        this.failedUrl = null;
        this.view = view;
        if (view) learnCentre(params, view);
        if (view) noticeReplacedRuns(view.generations);
        this.applyPreview();
        onFrameShown(this);
      } catch (e) {
        this.failedUrl = url;
        showError(e);
      } finally {
        clearTimeout(spin);
        this.spinner.hidden = true;
        this.inFlight = null;
        this.update();
        checkReady();
      }
    }
    // The shown image moved and scaled to where the wanted view will put it (pan and zoom feel
    // immediate); identity once the wanted frame is shown.
    applyPreview() {
      let tr = 'none';
      const v = this.view, pv = this.shownParams && predictedView(this.shownParams, v);
      if (v && pv && this.shownUrl !== this.wantedUrl()) {
        const k = pv.scale / v.scale;
        const dpr = S.size.dpr;
        const tx = (pv.ox - k * v.ox) / dpr, ty = (pv.oy - k * v.oy) / dpr;
        if (Math.abs(k - 1) > 1e-9 || Math.abs(tx) > 0.01 || Math.abs(ty) > 0.01) tr = `translate(${tx}px, ${ty}px) scale(${k})`;
      }
      this.img.style.transform = tr;
    }
    // Pixel of the wanted view under a client point (the image box without the preview transform).
    toViewPixel(cx, cy) {
      const br = this.box.getBoundingClientRect();
      const left = br.left + (parseFloat(this.img.style.left) || 0), top = br.top + (parseFloat(this.img.style.top) || 0);
      return [(cx - left) * S.size.dpr, (cy - top) * S.size.dpr];
    }
    // Client (CSS px) position of a pixel of the shown image (preview transform included).
    toClient(px, py) {
      const r = this.img.getBoundingClientRect(), nw = this.img.naturalWidth || S.size.w, nh = this.img.naturalHeight || S.size.h;
      return [r.left + px * r.width / nw, r.top + py * r.height / nh];
    }
  }
  const slots = { a: null, b: null };

  // The camera centre's pixel depends only on the frame size and whether the panel is shown.
  // A centre-camera frame gives it exactly; a fit frame, approximately (the fitted box's centre
  // is the bounds' centre when the walls lie on the bounds).
  function learnCentre(params, view) {
    const layers = params.layers ? params.layers.split(',') : [];
    const key = viewKey(params.width, params.height, layers);
    if (params.camera === 'center' && params.center) {
      const [cx, cy] = params.center.split(',').map(Number);
      const p = [view.ox + view.scale * cx, view.oy - view.scale * cy];
      const old = centreCache.get(key);
      centreCache.set(key, { p, exact: true });
      if (S.anchor && S.anchor.key === key && (!old || !old.exact)) {
        // The centre was estimated for this zoom or pan: put the anchored point back under its pixel.
        const s = view.scale * S.zoom / Number(params.zoom);
        const c = [S.anchor.w[0] - (S.anchor.p[0] - p[0]) / s, S.anchor.w[1] + (S.anchor.p[1] - p[1]) / s];
        S.anchor = null;
        if (S.camera === 'center' && S.center && Math.hypot(c[0] - S.center[0], c[1] - S.center[1]) * s > 0.5) {
          S.center = roundCentre(c);
          viewChanged();
        }
      }
    } else if (params.camera === 'fit' && !(centreCache.get(key) || {}).exact) {
      const b = S.info.a && S.info.a.bounds;
      if (b) {
        const cx = 0.5 * (b.min[0] + b.max[0]), cy = 0.5 * (b.min[1] + b.max[1]);
        centreCache.set(key, { p: [view.ox + view.scale * cx, view.oy - view.scale * cy], exact: false });
      }
    }
  }
  function centrePixel(w, h, layers) { return centreCache.get(viewKey(w, h, layers)) || null; }

  // The transform the wanted view will have, from a shown frame's (null when it cannot be known,
  // e.g. following the tip to another time).
  function predictedView(shownParams, v) {
    if (!v || !shownParams) return null;
    const want = frameParams(shownParams.run);
    if (want.width !== shownParams.width || want.height !== shownParams.height) return null;
    const layersShown = shownParams.layers ? shownParams.layers.split(',') : [];
    if (panelKey(layersShown) !== panelKey(S.layers)) return null;
    const c0 = centrePixel(want.width, want.height, S.layers);
    const k = S.zoom / Number(shownParams.zoom);
    const scale = v.scale * k;
    if (want.camera === 'center' && S.center) {
      if (!c0) return null;
      return { scale, ox: c0.p[0] - scale * S.center[0], oy: c0.p[1] + scale * S.center[1] };
    }
    if (want.camera !== shownParams.camera) return null;
    if (want.camera === 'follow' && want.t !== shownParams.t) return null;
    if (k === 1) return { scale, ox: v.ox, oy: v.oy };
    if (!c0) return null;
    const cw = [(c0.p[0] - v.ox) / v.scale, (v.oy - c0.p[1]) / v.scale];
    return { scale, ox: c0.p[0] - scale * cw[0], oy: c0.p[1] + scale * cw[1] };
  }
  // The transform of the wanted view now: predicted, or the shown frame's.
  function currentTransform(slot) {
    if (!slot.view) return null;
    return predictedView(slot.shownParams, slot.view) || slot.view;
  }

  // ------------------------------------------------------------------ readiness (tests)
  const readyWaiters = [];
  function allSettled() { return Object.values(slots).every((s) => !s || s.settled()); }
  function checkReady() {
    if (!allSettled()) return;
    while (readyWaiters.length) readyWaiters.shift()();
  }

  // ------------------------------------------------------------------ sizing
  function layoutMaps() {
    const a = slots.a.box;
    const cw = a.clientWidth, ch = a.clientHeight;
    if (!cw || !ch) return;
    const dpr = window.devicePixelRatio || 1;
    const even = (v) => Math.max(16, Math.min(4096, Math.floor(v / 2) * 2));
    const w = even(cw * dpr), h = even(ch * dpr);
    for (const slot of Object.values(slots)) {
      if (!slot) continue;
      const bw = slot.box.clientWidth || cw, bh = slot.box.clientHeight || ch;
      slot.img.style.width = `${w / dpr}px`;
      slot.img.style.height = `${h / dpr}px`;
      slot.img.style.left = `${Math.round((bw - w / dpr) / 2)}px`;
      slot.img.style.top = `${Math.round((bh - h / dpr) / 2)}px`;
      slot.overlay.width = Math.round(bw * dpr);
      slot.overlay.height = Math.round(bh * dpr);
      slot.overlay.style.width = `${bw}px`;
      slot.overlay.style.height = `${bh}px`;
    }
    if (w !== S.size.w || h !== S.size.h || dpr !== S.size.dpr) {
      S.size = { w, h, dpr };
      viewChanged();
    }
  }

  // ------------------------------------------------------------------ the view changes
  let hashTimer = null, lastHash = null;
  function viewChanged(opts) {
    if (!S.started) return;
    for (const slot of Object.values(slots)) if (slot) slot.update();
    syncControls();
    drawTimeline();
    drawPlotCursors();
    updateCommands();
    updateCompare();
    updatePlotValues();
    if (!(opts && opts.noHash)) scheduleHash();
    checkReady();
  }
  function setTime(t, opts) {
    if (!isFinite(t)) return;
    t = Math.min(S.t1, Math.max(S.t0, t));
    if (opts && opts.snap) t = Math.round(t * 1e6) / 1e6;   // a pointer position: µs is plenty
    if (t === S.t && !(opts && opts.force)) return;
    S.t = t;
    viewChanged(opts);
  }
  function setZoom(z, keepCamera) {
    if (!isFinite(z) || z <= 0) return;
    S.zoom = Math.min(1000, Math.max(0.001, Number(z.toPrecision(6))));
    if (!keepCamera && S.camera === 'center' && !S.center) S.center = boundsCentre();
    viewChanged();
  }
  // Centres are kept to the µm the URL carries, so the state, the link and the frame agree.
  function roundCentre(c) { return [Math.round(c[0] * 1e6) / 1e6, Math.round(c[1] * 1e6) / 1e6]; }
  function boundsCentre() {
    const b = S.info.a.bounds;
    return [0.5 * (b.min[0] + b.max[0]), 0.5 * (b.min[1] + b.max[1])];
  }
  // The world point at the centre of the wanted view.
  function currentCentre() {
    if (S.camera === 'center' && S.center) return S.center.slice();
    const slot = slots.a, tr = currentTransform(slot);
    const c0 = centrePixel(S.size.w, S.size.h, S.layers);
    if (tr && c0) return [(c0.p[0] - tr.ox) / tr.scale, (tr.oy - c0.p[1]) / tr.scale];
    return boundsCentre();
  }
  function setCamera(mode) {
    if (mode === 'center') S.center = roundCentre(currentCentre());
    S.camera = mode;
    S.anchor = null;
    viewChanged();
  }
  function fit() { S.camera = 'fit'; S.zoom = 1; S.anchor = null; viewChanged(); }
  function followTip() { S.camera = 'follow'; S.anchor = null; viewChanged(); }
  function zoomBy(factor) { setZoom(S.zoom * factor, true); }

  // Wheel zoom about a pixel: the world point under it stays under it.
  function zoomAbout(slot, clientX, clientY, factor) {
    const tr = currentTransform(slot);
    const newZoom = Math.min(1000, Math.max(0.001, Number((S.zoom * factor).toPrecision(6))));
    if (!tr) { setZoom(newZoom, true); return; }
    const [px, py] = slot.toViewPixel(clientX, clientY);
    const w = [(px - tr.ox) / tr.scale, (tr.oy - py) / tr.scale];
    let c0 = centrePixel(S.size.w, S.size.h, S.layers);
    if (!c0) c0 = { p: [S.size.w / 2, S.size.h / 2], exact: false };
    const s2 = tr.scale * newZoom / S.zoom;
    S.center = roundCentre([w[0] - (px - c0.p[0]) / s2, w[1] + (py - c0.p[1]) / s2]);
    S.camera = 'center';
    S.zoom = newZoom;
    S.anchor = c0.exact ? null : { w, p: [px, py], key: viewKey(S.size.w, S.size.h, S.layers) };
    viewChanged();
  }

  // ------------------------------------------------------------------ controls
  function syncControls() {
    $('time-readout').textContent = fmtTime(S.t);
    const a = S.info.a;
    if (a) {
      const frame = Math.round((Math.min(Math.max(S.t, a.first_time), a.last_time) - a.first_time) / (a.output_interval || 1));
      $('frame-readout').textContent = `frame ${Math.min(Math.max(frame, 0), a.frames - 1)}`;
    }
    $('duration-readout').textContent = fmtTime(S.t1);
    if ($('camera-select').value !== S.camera) $('camera-select').value = S.camera;
    const zi = $('zoom-input');
    if (document.activeElement !== zi) zi.value = String(Number(S.zoom.toPrecision(4)));
    $('btn-fit').classList.toggle('active', S.camera === 'fit' && S.zoom === 1);
    $('btn-follow').classList.toggle('active', S.camera === 'follow');
    for (const cb of document.querySelectorAll('#layers input')) {
      cb.checked = S.layers.includes(cb.value);
      cb.parentElement.classList.toggle('off', !cb.checked);
    }
    if (S.compare) {
      $('compare-mode').value = S.compareMode;
      $('map-b').hidden = S.compareMode !== 'side';
    }
    const play = $('btn-play');
    if (play.dataset.playing !== String(S.playing)) {
      play.dataset.playing = String(S.playing);
      play.classList.toggle('playing', S.playing);
      play.innerHTML = S.playing
        ? '<svg viewBox="0 0 16 16" width="12" height="12" aria-hidden="true"><rect x="3" y="2" width="3.5" height="12" fill="currentColor"/><rect x="9.5" y="2" width="3.5" height="12" fill="currentColor"/></svg>'
        : '<svg viewBox="0 0 16 16" width="12" height="12" aria-hidden="true"><path d="M4 2v12l10-6z" fill="currentColor"/></svg>';
      play.title = S.playing ? 'Pause (Space)' : 'Play (Space)';
    }
    updateMapLabels();
    const save = $('save-png');
    save.href = frameUrl('a');
    save.download = `${(a && a.title) || 'view'}_t${S.t.toFixed(3)}.png`;
  }
  function updateMapLabels() {
    if (!S.compare) { $('map-label-a').innerHTML = ''; return; }
    for (const r of ['a', 'b']) {
      const info = S.info[r];
      let text = `<span class="swatch" style="background:var(--run-${r})"></span><b>${r.toUpperCase()}</b> ${esc(info.path)}`;
      if (r === 'a' && S.compareMode === 'overlay') {
        text += ` <span class="dim">+ B's rod</span> <span class="swatch" style="background:var(--run-b)"></span>`;
        if (S.info.b.same_environment_as_a === false)
          text += ' <span class="map-warning">B ran in another environment (walls or lumen differ): its rod is drawn over A\'s map</span>';
      }
      if (S.t > info.last_time + 1e-9) text += ` <span class="dim">· ended at ${fmtTime(info.last_time)}</span>`;
      const el = $(`map-label-${r}`);
      if (el.dataset.html !== text) { el.dataset.html = text; el.innerHTML = text; }
    }
  }

  function buildLayerToggles() {
    const box = $('layers');
    box.innerHTML = '';
    // A layer that draws nothing for any run shown (the magnetic arrows of a run only pushed from
    // its root, the walls of a free rod) stays listed, so a view's layers keep their meaning in
    // its link and command, but greyed out and disabled.
    const withContent = new Set(runs().flatMap((r) => S.info[r].layers_with_content));
    for (const name of S.info.a.layers) {
      const label = document.createElement('label');
      const cb = document.createElement('input');
      cb.type = 'checkbox';
      cb.id = `layer-${name}`;
      cb.value = name;
      cb.checked = S.layers.includes(name);
      if (!withContent.has(name)) {
        cb.disabled = true;
        label.classList.add('empty');
        const what = S.info.a.layer_content[name];
        label.title = `${S.compare ? 'Neither run records' : 'This run does not record'} ${what}`;
      }
      cb.addEventListener('change', () => {
        const on = new Set(Array.from(document.querySelectorAll('#layers input')).filter((c) => c.checked).map((c) => c.value));
        S.layers = S.info.a.layers.filter((l) => on.has(l));
        cb.blur();
        viewChanged();
      });
      label.appendChild(cb);
      label.appendChild(document.createTextNode(name.replace('_', ' / ')));
      box.appendChild(label);
    }
  }

  // ------------------------------------------------------------------ playback
  let playLast = 0;
  function play(on) {
    if (on && S.t >= S.t1 - 1e-9) setTime(S.t0);
    S.playing = on;
    playLast = performance.now();
    if (on) requestAnimationFrame(tick);
    syncControls();
  }
  function tick(now) {
    if (!S.playing) return;
    const dt = Math.max(0, now - playLast) / 1000;
    playLast = now;
    const t = S.t + dt * S.speed;
    if (t >= S.t1) {
      setTime(S.t1, { noHash: false });
      if (!anyGrowing()) { play(false); return; }
    } else {
      setTime(t);
    }
    requestAnimationFrame(tick);
  }
  // Logged frames are at first_time + k * output_interval (run a's clock).
  function stepFrame(dir) {
    const a = S.info.a, dt = a.output_interval > 0 ? a.output_interval : 0.01;
    const k = (S.t - a.first_time) / dt;
    const eps = 1e-6;
    const next = dir > 0 ? Math.floor(k + eps) + 1 : Math.ceil(k - eps) - 1;
    setTime(a.first_time + next * dt);
  }

  // ------------------------------------------------------------------ timeline
  function timeAtClientX(el, x) {
    const r = el.getBoundingClientRect();
    const f = r.width > 0 ? Math.min(1, Math.max(0, (x - r.left) / r.width)) : 0;
    return S.t0 + f * (S.t1 - S.t0);
  }
  function fracOf(t) { return S.t1 > S.t0 ? (t - S.t0) / (S.t1 - S.t0) : 0; }

  function drawTimeline() {
    const track = $('timeline-track');
    const f = fracOf(S.t);
    $('timeline-handle').style.left = `${(f * 100).toFixed(4)}%`;
    $('timeline-played').style.width = `${(f * 100).toFixed(4)}%`;
    const canvas = $('timeline-ruler');
    const dpr = window.devicePixelRatio || 1;
    const w = track.clientWidth, h = track.clientHeight;
    if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr) || drawTimeline.range !== `${S.t0}|${S.t1}`) {
      canvas.width = Math.round(w * dpr);
      canvas.height = Math.round(h * dpr);
      drawTimeline.range = `${S.t0}|${S.t1}`;
      const g = canvas.getContext('2d');
      g.setTransform(dpr, 0, 0, dpr, 0, 0);
      g.clearRect(0, 0, w, h);
      const barY = $('timeline-played').offsetTop || 13;
      g.fillStyle = '#E4E7EB';
      g.fillRect(0, barY, w, 6);
      const tk = timeTicks(w);
      const dec = decimalsFor(tk.step);
      g.font = '10px system-ui, "DejaVu Sans", sans-serif';
      g.textAlign = 'center';
      g.textBaseline = 'alphabetic';
      for (const v of tk.values) {
        const x = Math.round(fracOf(v) * w) + 0.5;
        g.fillStyle = '#9AA5B1';
        g.fillRect(x - 0.5, barY + 6, 1, 4);
        g.fillStyle = '#7B8794';
        // The end labels are kept whole inside the track ("0.00" lost its first digit).
        const label = v.toFixed(dec), half = g.measureText(label).width / 2 + 2;
        g.fillText(label, Math.min(w - half, Math.max(half, x)), h - 2);
      }
    }
  }
  function timeTicks(width) { return ticks(S.t0, S.t1, Math.max(2, Math.floor(width / 90))); }

  function initTimeline() {
    const track = $('timeline-track');
    let dragging = false, wasPlaying = false;
    track.addEventListener('pointerdown', (e) => {
      if (e.button !== 0 || e.target.classList.contains('event-mark')) return;
      dragging = true;
      wasPlaying = S.playing;
      if (S.playing) play(false);
      try { track.setPointerCapture(e.pointerId); } catch (_) { /* synthetic pointers */ }
      setTime(timeAtClientX(track, e.clientX), { snap: true });
      e.preventDefault();
    });
    track.addEventListener('pointermove', (e) => {
      if (dragging) setTime(timeAtClientX(track, e.clientX), { snap: true });
    });
    const end = (e) => {
      if (!dragging) return;
      dragging = false;
      try { track.releasePointerCapture(e.pointerId); } catch (_) { /* already released */ }
      if (wasPlaying) play(true);
    };
    track.addEventListener('pointerup', end);
    track.addEventListener('pointercancel', end);
  }

  const EVENT_TEXT = { contact_start: 'wall contact starts', contact_end: 'wall contact ends', goal: 'goal reached', failure: 'run failed', warning: 'warning' };
  const events = { a: [], b: [] };
  async function loadEvents() {
    for (const r of runs()) {
      try { events[r] = (await getJSON('/api/events', { run: r })).events || []; } catch (e) { showError(e); }
    }
    renderEvents();
  }
  function renderEvents() {
    const box = $('timeline-events');
    box.innerHTML = '';
    const frag = document.createDocumentFragment();
    for (const r of runs()) {
      for (const ev of events[r]) {
        const m = document.createElement('div');
        m.className = `event-mark ${ev.kind} run-${r}`;
        m.style.left = `${(fracOf(ev.t) * 100).toFixed(4)}%`;
        m.title = `${S.compare ? r.toUpperCase() + ': ' : ''}${ev.label || EVENT_TEXT[ev.kind] || ev.kind} at ${fmtTime(ev.t)}`;
        m.dataset.t = ev.t;
        m.dataset.kind = ev.kind;
        m.addEventListener('pointerdown', (e) => e.stopPropagation());
        m.addEventListener('click', (e) => { e.stopPropagation(); setTime(ev.t); });
        frag.appendChild(m);
      }
    }
    box.appendChild(frag);
    // The run's warnings under its summary, each a link to where it first happened.
    const list = $('run-warnings');
    list.innerHTML = '';
    for (const r of runs()) {
      for (const ev of events[r]) {
        if (ev.kind !== 'warning') continue;
        // A button, so the keyboard reaches it (Tab, then Enter) as the mouse does.
        const note = document.createElement('button');
        note.type = 'button';
        note.className = 'warning-note';
        note.textContent = `${S.compare ? r.toUpperCase() + ': ' : ''}${ev.label}`;
        note.title = `go to t = ${fmtTime(ev.t)}`;
        note.dataset.t = ev.t;
        note.addEventListener('click', () => setTime(ev.t));
        list.appendChild(note);
      }
    }
  }

  // ------------------------------------------------------------------ plots
  const RUN_COLOURS = { a: '#1E4FD8', b: '#E8590C' };
  const plots = [];   // {channel, reduce, label, removable, el, canvas, data: {a, b}, base}
  function channelInfo(name) {
    for (const r of runs()) {
      const c = (S.info[r].channels || []).find((ch) => ch.name === name);
      if (c) return c;
    }
    return null;
  }
  function reduceChoices(layout) {
    if (layout === 'node_vectors') return [['max', 'max over nodes'], ['norm', 'norm of all'], ['sum', 'magnitude of sum']];
    // Vectors and scalars: the server's default (magnitude; the first value) needs no reduce.
    if (layout === 'vector') return [['', 'magnitude'], ['x', 'x'], ['y', 'y']];
    return [['', 'value']];
  }
  // The plots' time axis is the timeline's: same left and right, whatever scrollbar the list has.
  function plotArea() {
    const list = $('plot-list').getBoundingClientRect(), track = $('timeline-track').getBoundingClientRect();
    const x0 = Math.round(track.left - list.left);
    return { x0, x1: Math.max(x0 + 1, Math.round(track.right - list.left)) };
  }
  function addPlot(channel, reduce, label, removable) {
    const c = channelInfo(channel);
    if (!c) return;
    if (plots.some((p) => p.channel === channel && p.reduce === reduce)) { showStatus(`${channel}${reduce ? ` (${reduce})` : ''} is already plotted`); return; }
    const el = document.createElement('div');
    el.className = 'plot';
    const canvas = document.createElement('canvas');
    el.appendChild(canvas);
    const p = { channel, reduce, label, removable, el, canvas, data: {}, unit: c.unit, base: null };
    if (removable) {
      const x = document.createElement('button');
      x.className = 'plot-close';
      x.type = 'button';
      x.title = 'Remove this plot';
      x.textContent = '×';
      x.addEventListener('click', () => {
        plots.splice(plots.indexOf(p), 1);
        el.remove();
      });
      el.appendChild(x);
    }
    canvas.addEventListener('click', (e) => {
      const r = canvas.getBoundingClientRect();
      const a = plotArea();
      const x = e.clientX - r.left;
      if (x < a.x0 - 4 || x > a.x1 + 4) return;
      setTime(S.t0 + Math.min(1, Math.max(0, (x - a.x0) / (a.x1 - a.x0))) * (S.t1 - S.t0), { snap: true });
    });
    $('plot-list').appendChild(el);
    if (removable) el.scrollIntoView({ block: 'nearest' });
    plots.push(p);
    loadPlot(p);
  }
  function plotted(p, r) { return (S.info[r].channels || []).some((c) => c.name === p.channel); }
  async function loadPlot(p) {
    const a = plotArea();
    const points = Math.max(1, Math.min(10000, Math.round(a.x1 - a.x0)));
    p.valuesT = null;
    for (const r of runs()) {
      if (!plotted(p, r)) { p.data[r] = null; continue; }
      try {
        p.data[r] = await getJSON('/api/series', { channel: p.channel, reduce: p.reduce || undefined, points, run: r });
      } catch (e) { p.data[r] = null; showError(e); }
    }
    p.base = null;
    drawPlot(p);
    updatePlotValues();
  }
  // The readouts at the time cursor are the values the map shows at that time (/api/value),
  // not the extremes of the bucket the curve draws there (which differed from the map's HUD
  // wherever a pixel column holds several frames). One set of requests in flight; the last
  // time asked wins.
  let plotValuesBusy = false;
  async function updatePlotValues() {
    const t = S.t;
    const stale = plots.filter((p) => p.valuesT !== t);
    if (plotValuesBusy || !stale.length) return;
    plotValuesBusy = true;
    try {
      await Promise.all(stale.map(async (p) => {
        const values = {};
        for (const r of runs()) {
          if (!plotted(p, r)) continue;
          values[r] = (await getJSON('/api/value', { channel: p.channel, reduce: p.reduce || undefined, t: fmtParamT(t), run: r })).value;
        }
        p.values = values;
        p.valuesT = t;
        drawPlot(p);
      }));
    } catch (e) {
      // No readout rather than an earlier time's under this one.
      for (const p of stale) if (p.valuesT !== t) { p.values = null; p.valuesT = t; drawPlot(p); }
      showError(e);
    } finally {
      plotValuesBusy = false;
      if (plots.some((p) => p.valuesT !== S.t)) updatePlotValues();
    }
  }
  function reloadPlots() { for (const p of plots) loadPlot(p); }

  function drawPlotBase(p, w, h, dpr) {
    const base = document.createElement('canvas');
    base.width = Math.round(w * dpr);
    base.height = Math.round(h * dpr);
    const g = base.getContext('2d');
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.fillStyle = '#FFFFFF';
    g.fillRect(0, 0, w, h);
    const area = plotArea();
    const top = 16, bottom = h - 6;
    let lo = Infinity, hi = -Infinity;
    for (const r of runs()) {
      const d = p.data[r];
      if (!d) continue;
      for (const v of d.min) if (v !== null && isFinite(v)) lo = Math.min(lo, v);
      for (const v of d.max) if (v !== null && isFinite(v)) hi = Math.max(hi, v);
    }
    const unit = displayUnit(p.unit, Math.max(Math.abs(lo), Math.abs(hi)));
    p.display = unit;
    g.font = '10.5px system-ui, "DejaVu Sans", sans-serif';
    // time grid, shared with the timeline's ticks
    const tk = timeTicks(area.x1 - area.x0);
    g.fillStyle = '#F0F2F4';
    for (const v of tk.values) g.fillRect(Math.round(area.x0 + fracOf(v) * (area.x1 - area.x0)), top, 1, bottom - top);
    if (!(hi >= lo)) {
      g.fillStyle = '#9AA5B1';
      g.textBaseline = 'middle';
      g.fillText('no data', area.x0 + 8, (top + bottom) / 2);
    } else {
      if (lo >= 0) lo = 0;
      // A constant series gets a range of its own size; one that is all zero, a range of one
      // display unit (1e-9 N showed as "0.000001 mN" beside a flat zero).
      if (hi - lo <= 0) { hi = lo + (Math.abs(lo) > 0 ? Math.abs(lo) * 0.1 : 1 / unit.f); }
      const pad = (hi - lo) * 0.06;
      const ylo = lo === 0 ? 0 : lo - pad, yhi = hi + pad;
      const Y = (v) => bottom - (v - ylo) / (yhi - ylo) * (bottom - top);
      const X = (t) => area.x0 + fracOf(t) * (area.x1 - area.x0);
      const yt = ticks(ylo * unit.f, yhi * unit.f, Math.max(2, Math.floor((bottom - top) / 22)));
      const dec = decimalsFor(yt.step);
      g.textAlign = 'right';
      g.textBaseline = 'middle';
      p.canvas.dataset.yTicks = yt.values.map((v) => v.toFixed(dec)).join(' ');  // the axis as drawn, for tests
      for (const v of yt.values) {
        const y = Math.round(Y(v / unit.f)) + 0.5;
        g.fillStyle = '#EDF0F2';
        g.fillRect(area.x0, y - 0.5, area.x1 - area.x0, 1);
        g.fillStyle = '#7B8794';
        g.fillText(v.toFixed(dec), area.x0 - 5, y);
      }
      g.save();
      g.beginPath();
      g.rect(area.x0, top - 1, area.x1 - area.x0, bottom - top + 2);
      g.clip();
      for (const r of runs()) {
        const d = p.data[r];
        if (!d || !d.t.length) continue;
        const col = RUN_COLOURS[r];
        // min/max band: spikes survive the decimation
        g.beginPath();
        for (let i = 0; i < d.t.length; i++) { const x = X(d.t[i]), y = Y(d.max[i]); i ? g.lineTo(x, y) : g.moveTo(x, y); }
        for (let i = d.t.length - 1; i >= 0; i--) g.lineTo(X(d.t[i]), Y(d.min[i]));
        g.closePath();
        g.globalAlpha = 0.22;
        g.fillStyle = col;
        g.fill();
        g.globalAlpha = 1;
        g.lineWidth = 1.25;
        g.strokeStyle = col;
        g.beginPath();
        for (let i = 0; i < d.t.length; i++) { const x = X(d.t[i]), y = Y(d.max[i]); i ? g.lineTo(x, y) : g.moveTo(x, y); }
        g.stroke();
        g.lineWidth = 0.75;
        g.globalAlpha = 0.7;
        g.beginPath();
        for (let i = 0; i < d.t.length; i++) { const x = X(d.t[i]), y = Y(d.min[i]); i ? g.lineTo(x, y) : g.moveTo(x, y); }
        g.stroke();
        g.globalAlpha = 1;
      }
      g.restore();
    }
    g.strokeStyle = '#D9DEE3';
    g.lineWidth = 1;
    g.strokeRect(area.x0 + 0.5, top - 0.5, area.x1 - area.x0 - 1, bottom - top + 1);
    // title: name and unit on the left of the plot area
    g.textAlign = 'left';
    g.textBaseline = 'alphabetic';
    g.fillStyle = '#1F2933';
    g.font = '600 11px system-ui, "DejaVu Sans", sans-serif';
    const title = `${p.label}`;
    g.fillText(title, area.x0 + 2, 12);
    const tw = g.measureText(title).width;
    g.font = '10.5px system-ui, "DejaVu Sans", sans-serif';
    g.fillStyle = '#7B8794';
    g.fillText(`[${unit.unit}]  ${p.channel}${p.reduce && channelInfo(p.channel) && channelInfo(p.channel).layout !== 'scalars' ? ' · ' + p.reduce : ''}`, area.x0 + tw + 8, 12);
    return base;
  }
  function drawPlot(p) {
    const w = p.canvas.clientWidth, h = p.canvas.clientHeight;
    if (!w || !h) return;
    const dpr = window.devicePixelRatio || 1;
    const ar = plotArea();
    const key = `${w}x${h}@${dpr}|${S.t0}|${S.t1}|${ar.x0}|${ar.x1}`;
    if (!p.base || p.baseKey !== key) { p.base = drawPlotBase(p, w, h, dpr); p.baseKey = key; }
    if (p.canvas.width !== p.base.width || p.canvas.height !== p.base.height) {
      p.canvas.width = p.base.width;
      p.canvas.height = p.base.height;
    }
    const g = p.canvas.getContext('2d');
    g.setTransform(1, 0, 0, 1, 0, 0);
    g.drawImage(p.base, 0, 0);
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    const area = plotArea();
    const x = Math.round(area.x0 + fracOf(S.t) * (area.x1 - area.x0)) + 0.5;
    g.fillStyle = '#2563EB';
    g.fillRect(x - 0.75, 15, 1.5, h - 20);
    // values at the cursor, right-aligned in the title row
    g.font = '10.5px ui-monospace, "DejaVu Sans Mono", monospace';
    g.textAlign = 'right';
    g.textBaseline = 'alphabetic';
    let xr = Math.min(area.x1, w - (p.removable ? 20 : 0)) - 4;
    const unit = p.display || displayUnit(p.unit, 0);
    const said = [];
    for (const r of runs().slice().reverse()) {
      const v = p.values ? p.values[r] : null;
      if (v === null || v === undefined) continue;
      const text = `${S.compare ? r.toUpperCase() + ' ' : ''}${fmtSig(v * unit.f, 4)} ${unit.unit}`;
      g.fillStyle = RUN_COLOURS[r];
      g.fillText(text, xr, 12);
      xr -= g.measureText(text).width + 12;
      said.unshift(text);
    }
    // The readout drawn is also the canvas's text, for screen readers (and the browser test).
    if (p.valuesT !== null && p.valuesT !== undefined)
      p.canvas.setAttribute('aria-label', `${p.label} at ${fmtTime(p.valuesT)}: ${said.join(', ') || 'no value'}`);
  }
  let plotCursorQueued = false;
  function drawPlotCursors() {
    if (plotCursorQueued) return;
    plotCursorQueued = true;
    requestAnimationFrame(() => { plotCursorQueued = false; for (const p of plots) drawPlot(p); });
  }
  function initPlots() {
    const sel = $('plot-channel');
    sel.innerHTML = '';
    const names = new Map();
    for (const r of runs()) for (const c of S.info[r].channels || []) if (!names.has(c.name)) names.set(c.name, c);
    for (const c of names.values()) {
      const o = document.createElement('option');
      o.value = c.name;
      o.textContent = `${c.name} [${c.unit}]`;
      sel.appendChild(o);
    }
    const refreshReduce = () => {
      const c = names.get(sel.value);
      const rs = $('plot-reduce');
      rs.innerHTML = '';
      for (const [v, text] of reduceChoices(c ? c.layout : 'scalars')) {
        const o = document.createElement('option');
        o.value = v;
        o.textContent = text;
        rs.appendChild(o);
      }
      rs.disabled = !c || c.layout === 'scalars';
    };
    sel.addEventListener('change', () => { refreshReduce(); sel.blur(); });
    $('plot-reduce').addEventListener('change', () => $('plot-reduce').blur());
    refreshReduce();
    $('plot-add').addEventListener('click', () => {
      const c = names.get(sel.value);
      if (!c) return;
      const reduce = $('plot-reduce').value;
      const label = c.layout === 'scalars' ? c.name : `${c.name} (${$('plot-reduce').selectedOptions[0].textContent})`;
      addPlot(c.name, reduce, label, true);
    });
    if (channelInfo('tip/error')) addPlot('tip/error', '', 'tip error', false);
    if (channelInfo('force/actuation')) addPlot('force/actuation', 'sum', 'magnetic force', false);
    if (channelInfo('feed/force')) addPlot('feed/force', '', 'feed force', false);
    if (channelInfo('force/contact')) addPlot('force/contact', 'max', 'largest contact force', false);
    $('plot-legend').innerHTML = S.compare
      ? `<span><i style="background:${RUN_COLOURS.a}"></i>A ${esc(S.info.a.path)}</span><span><i style="background:${RUN_COLOURS.b}"></i>B ${esc(S.info.b.path)}</span>`
      : '<span class="dim">band: min–max per pixel column · click a plot to seek</span>';
  }

  // ------------------------------------------------------------------ hover readout
  const nodesCache = new Map();   // `${run}|${time}` -> Promise of /api/nodes
  function nodesAt(run, t) {
    const key = `${run}|${t}`;
    if (!nodesCache.has(key)) {
      if (nodesCache.size > 64) nodesCache.delete(nodesCache.keys().next().value);
      const p = getJSON('/api/nodes', { t: fmtParamT(t), run });
      p.catch((e) => { nodesCache.delete(key); showError(e); });
      nodesCache.set(key, p);
    }
    return nodesCache.get(key);
  }
  let hoverAt = null;   // {slot, x, y}: the last pointer position over a map
  let hoverSeq = 0;
  async function updateHover() {
    const seq = ++hoverSeq;
    const h = hoverAt;
    if (!h || !h.slot.view) { clearHover(); return; }
    const slot = h.slot;
    const view = slot.view;
    let data;
    try { data = await nodesAt(slot.run, view.time); } catch (_) { return; }
    if (seq !== hoverSeq) return;
    const tr = view;
    let best = null, bestD = Infinity;
    for (const n of data.nodes) {
      const [cx, cy] = slot.toClient(tr.ox + tr.scale * n.position[0], tr.oy - tr.scale * n.position[1]);
      const d = Math.hypot(cx - h.x, cy - h.y);
      if (d < bestD) { bestD = d; best = { n, cx, cy }; }
    }
    if (!best || bestD > HOVER_RADIUS_PX) { clearHover(slot); return; }
    showHover(slot, data, best);
  }
  function clearHover(slot) {
    for (const s of Object.values(slots)) if (s && (!slot || s === slot)) {
      const g = s.overlay.getContext('2d');
      g.clearRect(0, 0, s.overlay.width, s.overlay.height);
    }
    $('hover-tip').hidden = true;
    const ro = $('hover-readout');
    ro.innerHTML = '<span class="dim">hover the rod (within 15 px of a node)</span>';
    delete ro.dataset.node;
  }
  function showHover(slot, data, best) {
    const n = best.n;
    const count = data.nodes.length;
    // marker on the map
    const g = slot.overlay.getContext('2d');
    const dpr = window.devicePixelRatio || 1;
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.clearRect(0, 0, slot.overlay.width, slot.overlay.height);
    const br = slot.box.getBoundingClientRect();
    const x = best.cx - br.left, y = best.cy - br.top;
    g.lineWidth = 2;
    g.strokeStyle = '#FFFFFF';
    g.beginPath(); g.arc(x, y, 7, 0, 2 * Math.PI); g.stroke();
    g.lineWidth = 1.5;
    g.strokeStyle = '#D9480F';
    g.beginPath(); g.arc(x, y, 7, 0, 2 * Math.PI); g.stroke();
    // readout panel: values from the log, never from pixels
    const tip = n.index === count - 1 ? ' <span class="dim">(tip)</span>' : n.index === 0 ? ' <span class="dim">(base)</span>' : '';
    const mm = (v) => (v * 1e3).toFixed(3);
    let html = `<div class="node-head"><span><b>node <span id="hover-node">${n.index}</span></b>${tip}</span>` +
      `<span class="dim">${S.compare ? 'run ' + slot.run.toUpperCase() + ' · ' : ''}t ${data.time.toFixed(3)} s · ` +
      `${data.between ? `between frames ${data.between[0]} and ${data.between[1]}` : `frame ${data.frame}`}</span></div>` +
      '<table><thead><tr><th></th><th>x</th><th>y</th><th>|·|</th></tr></thead><tbody>' +
      `<tr><th>position [mm]</th><td id="hover-x" data-m="${n.position[0]}">${mm(n.position[0])}</td><td id="hover-y" data-m="${n.position[1]}">${mm(n.position[1])}</td><td></td></tr>`;
    if (n.velocity) {
      html += `<tr><th>velocity [mm/s]</th><td>${mm(n.velocity[0])}</td><td>${mm(n.velocity[1])}</td>` +
        `<td id="hover-speed" data-m="${n.speed}">${mm(n.speed)}</td></tr>`;
    }
    const forces = Object.entries(n.forces || {});
    if (forces.length) {
      html += '<tr><th colspan="4" class="dim" style="padding-top:5px">forces on the node [mN]</th></tr>';
      for (const [name, f] of forces) {
        const mag = Math.hypot(f[0], f[1]);
        html += `<tr data-force="${esc(name)}" title="${esc(name)}: ${f[0]} N, ${f[1]} N"><th>${esc(name.replace(/^force\//, ''))}</th>` +
          `<td>${fmtForce(f[0] * 1e3)}</td><td>${fmtForce(f[1] * 1e3)}</td><td>${fmtForce(mag * 1e3)}</td></tr>`;
      }
    }
    html += '</tbody></table>';
    const ro = $('hover-readout');
    ro.innerHTML = html;
    ro.dataset.node = n.index;
    ro.dataset.run = slot.run;
    ro.dataset.pointer = `${hoverAt ? hoverAt.x : best.cx},${hoverAt ? hoverAt.y : best.cy}`;
    // tooltip beside the cursor
    const tipEl = $('hover-tip');
    tipEl.textContent = `node ${n.index} · ${mm(n.position[0])}, ${mm(n.position[1])} mm · ${mm(n.speed || 0)} mm/s`;
    tipEl.hidden = false;
    tipEl.style.left = `${Math.min(window.innerWidth - tipEl.offsetWidth - 8, best.cx + 14)}px`;
    tipEl.style.top = `${best.cy + 14}px`;
  }
  function onFrameShown(slot) {
    if (hoverAt && hoverAt.slot === slot) updateHover();
    if (slot.run === 'a') updateCommands();
  }

  // ------------------------------------------------------------------ map interaction
  function initMapInteraction(slot) {
    const box = slot.box;
    let pan = null;
    box.addEventListener('wheel', (e) => {
      e.preventDefault();
      const unit = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? 400 : 1;
      const factor = Math.exp(-e.deltaY * unit * 0.0015);
      zoomAbout(slot, e.clientX, e.clientY, Math.min(4, Math.max(0.25, factor)));
    }, { passive: false });
    box.addEventListener('pointerdown', (e) => {
      if (e.button !== 0) return;
      const tr = currentTransform(slot);
      if (!tr) return;
      const [px, py] = slot.toViewPixel(e.clientX, e.clientY);
      pan = { x: e.clientX, y: e.clientY, moved: false, tr, px, py, c: currentCentre(), id: e.pointerId };
      try { box.setPointerCapture(e.pointerId); } catch (_) { /* synthetic pointers */ }
    });
    box.addEventListener('pointermove', (e) => {
      hoverAt = { slot, x: e.clientX, y: e.clientY };
      if (pan) {
        const dx = e.clientX - pan.x, dy = e.clientY - pan.y;
        if (!pan.moved && Math.hypot(dx, dy) < 3) { updateHover(); return; }
        if (!pan.moved) { pan.moved = true; box.classList.add('panning'); clearHover(); }
        const s = pan.tr.scale;
        const k = S.size.dpr;  // view px per CSS px
        S.camera = 'center';
        S.center = roundCentre([pan.c[0] - dx * k / s, pan.c[1] + dy * k / s]);
        const c0 = centrePixel(S.size.w, S.size.h, S.layers);
        S.anchor = c0 && c0.exact ? null : {
          w: [(pan.px - pan.tr.ox) / s, (pan.tr.oy - pan.py) / s], p: [pan.px + dx * k, pan.py + dy * k],
          key: viewKey(S.size.w, S.size.h, S.layers),
        };
        viewChanged();
        return;
      }
      updateHover();
    });
    const end = (e) => {
      if (!pan) return;
      try { box.releasePointerCapture(pan.id); } catch (_) { /* released */ }
      box.classList.remove('panning');
      pan = null;
      if (e.type === 'pointerup') updateHover();
    };
    box.addEventListener('pointerup', end);
    box.addEventListener('pointercancel', end);
    box.addEventListener('pointerleave', () => { if (!pan) { hoverAt = null; hoverSeq++; clearHover(); } });
  }

  // ------------------------------------------------------------------ URL fragment
  function buildHash() {
    const parts = [`t=${fmtParamT(S.t)}`, `zoom=${fmtZoom(S.zoom)}`, `camera=${S.camera}`];
    if (S.camera === 'center' && S.center) parts.push(`center=${fmtCoord(S.center[0])},${fmtCoord(S.center[1])}`);
    parts.push(`layers=${S.layers.join(',')}`);
    if (S.compare) parts.push(`compare=${S.compareMode}`);
    return parts.join('&');
  }
  function scheduleHash() {
    if (hashTimer) return;
    hashTimer = setTimeout(() => {
      hashTimer = null;
      const h = buildHash();
      if (h === lastHash) return;
      lastHash = h;
      history.replaceState(null, '', `${location.pathname}${location.search}#${h}`);
    }, 200);
  }
  // Apply a view string ("t=..&zoom=..&..."): a fragment or a bookmark's view.
  function applyView(text) {
    const q = new URLSearchParams(text.replace(/^#/, ''));
    const problems = [];
    if (q.has('zoom')) {
      const z = Number(q.get('zoom'));
      if (isFinite(z) && z > 0) S.zoom = Math.min(1000, Math.max(0.001, z)); else problems.push('zoom');
    }
    if (q.has('center')) {
      const c = q.get('center').split(',').map(Number);
      if (c.length === 2 && c.every(isFinite)) { S.center = c; S.camera = 'center'; } else problems.push('center');
    }
    if (q.has('camera')) {
      const cam = q.get('camera') === 'centre' ? 'center' : q.get('camera');
      if (['fit', 'follow', 'center'].includes(cam)) {
        S.camera = cam;
        if (cam === 'center' && !S.center) S.center = boundsCentre();
      } else problems.push('camera');
    }
    if (q.has('layers')) {
      const want = q.get('layers').split(',').filter((l) => l);
      const known = S.info.a.layers;
      const bad = want.filter((l) => !known.includes(l));
      if (bad.length) problems.push(`layers (${bad.join(', ')})`);
      S.layers = known.filter((l) => want.includes(l));
    }
    if (q.has('compare') && S.compare) {
      const m = q.get('compare');
      if (m === 'side' || m === 'overlay') S.compareMode = m; else problems.push('compare');
    }
    S.anchor = null;
    if (problems.length) showError(`link: ignored bad ${problems.join(', ')}`);
    if (q.has('t')) {
      const t = Number(q.get('t'));
      if (isFinite(t)) S.t = Math.min(S.t1, Math.max(S.t0, t)); else showError('link: ignored bad t');
    }
    lastHash = null;
    viewChanged();
  }

  // ------------------------------------------------------------------ summary
  function renderSummary() {
    const cols = runs().filter((r) => S.info[r]);
    const sums = cols.map((r) => S.info[r].summary);
    if (sums.every((s) => !s)) {
      const killed = cols.some((r) => S.info[r].state === 'killed');
      const why = anyGrowing() ? 'run in progress: the summary appears when it ends'
        : killed ? 'no summary.json: the run was killed before its end (kill -9, a crash, out of memory); the log ends with the last frame it wrote'
          : 'no summary.json, and no run is writing it (the directory was copied without it?)';
      $('summary').innerHTML = `<span class="dim">${why}</span>`;
      return;
    }
    const nav = (s) => (s && s.navigation) || {};
    const mm = (v) => (v === null || v === undefined ? '–' : `${(v * 1e3).toFixed(3)} mm`);
    // In mN up to 1 N, in N above (a crammed feed's 6102 mN read as its HUD's 6.10 N does not).
    const force = (v) => (v === null || v === undefined ? '–'
      : Math.abs(v) >= 1 ? `${fmtSig(v, 4)} N` : `${fmtSig(v * 1e3, 4)} mN`);
    const sec = (v) => (v === null || v === undefined ? '–' : `${Number(v).toFixed(3)} s`);
    const rows = [
      ['result', (s) => (!s ? ['–', ''] : s.ok ? ['ok', 'ok'] : [s.stopped_by ? 'stopped' : 'failed', 'bad'])],
      ['goal reached at', (s) => {
        const n = nav(s);
        if (!s || n.goal_reached === undefined || n.goal_reached === null) return ['–', ''];
        return n.goal_reached ? [sec(n.goal_time), 'ok'] : ['no', 'bad'];
      }, 'nav'],
      ['tip error RMS', (s) => [mm(nav(s).tip_error_rms), ''], 'steer'],
      ['tip error max', (s) => [mm(nav(s).tip_error_max), ''], 'steer'],
      ['contact max', (s) => [force(nav(s).contact_force_max), ''], 'nav'],
      ['magnetic max', (s) => [force(nav(s).actuation_force_max), ''], 'steer'],
      ['feed max', (s) => [force((nav(s).advance || {}).feed_force_max), ''], 'feed'],
      ['fed length', (s) => [mm((nav(s).advance || {}).fed_length), ''], 'feed'],
      ['simulated', (s) => [s ? sec(s.simulated_time) : '–', '']],
      ['wall time', (s) => [s ? sec(s.wall_time) : '–', '']],
      ['real-time factor', (s) => [s && s.real_time_factor ? `${fmtSig(s.real_time_factor, 3)}×` : '–', '']],
      ['steps (rejected)', (s) => [s ? `${s.steps}${s.rejected_steps ? ` (${s.rejected_steps})` : ''}` : '–', '']],
    ];
    let html = '<table class="summary-table"><thead><tr><th></th>' +
      (cols.length > 1 ? cols.map((r) => `<th style="color:var(--run-${r})">${r.toUpperCase()}</th>`).join('') : '') +
      '</tr></thead><tbody>';
    // Rows only where a run has them: the navigation's for a run in vessels (not a free rod's);
    // the feed's for a run whose root is fed; the tip's tracking and magnetic force unless every
    // run is only pushed from its root (nothing steers its tip: its log has no tip error, and
    // its summary's is against a target nothing followed).
    const logs = (r, name) => (S.info[r].channels || []).some((c) => c.name === name);
    const shown = {
      nav: sums.some((s) => s && s.navigation),
      feed: sums.some((s) => nav(s).advance),
    };
    shown.steer = shown.nav && !cols.every((r) => logs(r, 'feed/force') && !logs(r, 'tip/error'));
    for (const [name, f, only] of rows) {
      if (only && !shown[only]) continue;
      html += `<tr><th>${name}</th>`;
      for (let i = 0; i < cols.length; i++) {
        const [text, cls] = f(sums[i]);
        html += `<td class="${cls}" data-key="${name}">${text}</td>`;
      }
      html += '</tr>';
    }
    html += '</tbody></table>';
    cols.forEach((r, i) => {
      const s = sums[i];
      if (s && !s.ok && s.failure) {
        // A button, as the warnings are: it goes to the last frame before the failure.
        const last = S.info[r].last_time;
        html += `<button type="button" class="failure-note" data-t="${last}" title="go to the last frame, t = ${fmtTime(last)}">` +
          `${cols.length > 1 ? `<b>${r.toUpperCase()}</b> ` : ''}${esc(s.failure)}</button>`;
      }
    });
    $('summary').innerHTML = html;
    for (const note of $('summary').querySelectorAll('.failure-note')) {
      note.addEventListener('click', () => setTime(Number(note.dataset.t)));
    }
  }

  // ------------------------------------------------------------------ compare
  let compareBusy = false, compareShownT = null;
  async function updateCompare() {
    if (!S.compare || compareBusy || compareShownT === S.t) return;
    compareBusy = true;
    const t = S.t;
    try {
      const c = await getJSON('/api/compare', { t: fmtParamT(t) });
      const el = $('tip-distance');
      el.textContent = `${(c.tip_distance * 1e3).toFixed(4)} mm`;
      el.dataset.m = c.tip_distance;
      el.dataset.t = fmtParamT(t);
      compareShownT = t;
    } catch (e) {
      compareShownT = t;
      showError(e);
    } finally {
      compareBusy = false;
      if (compareShownT !== S.t) updateCompare();
    }
  }

  // ------------------------------------------------------------------ a run replaced on disk
  // The server opens a run again when its log was replaced (the run repeated with --force into
  // its directory); this page's timeline, plots and bookmarks describe the old one.
  function noticeReplacedRuns(generations) {
    for (const [r, g] of Object.entries(generations || {}))
      if (S.info[r] && S.info[r].generation !== g)
        showError(`run ${r} was replaced on disk (a new run in its directory): reload the page to view it`);
  }

  // ------------------------------------------------------------------ live follow
  let liveTimer = null;
  function anyGrowing() { return runs().some((r) => S.info[r] && S.info[r].growing); }
  function setRange() {
    const a = S.info.a, b = S.info.b;
    S.t0 = S.compare ? Math.min(a.first_time, b.first_time) : a.first_time;
    S.t1 = S.compare ? Math.max(a.last_time, b.last_time) : a.last_time;
  }
  function scheduleLive() {
    $('live-badge').hidden = !anyGrowing();
    clearTimeout(liveTimer);
    if (anyGrowing()) liveTimer = setTimeout(pollLive, 1000);
  }
  async function pollLive() {
    const atEnd = S.t >= S.t1 - 1e-9;
    const oldT1 = S.t1;
    const hadSummary = runs().map((r) => !!S.info[r].summary);
    const wasGrowing = runs().map((r) => !!S.info[r].growing);
    try {
      for (const r of runs()) if (S.info[r].growing) S.info[r] = await getJSON('/api/run', { run: r });
    } catch (e) { showError(e); scheduleLive(); return; }
    setRange();
    if (!S.exportTouched) setExportDefaults();
    if (S.t1 !== oldT1) {
      drawTimeline.range = null;
      if (atEnd) S.t = S.t1;
      // Frames at the same time but a longer log render the same; the series and events grow.
      reloadPlots();
      loadEvents();
      viewChanged({ noHash: false });
    }
    const ended = runs().filter((r, i) => wasGrowing[i] && !S.info[r].growing);
    if (runs().some((r, i) => !!S.info[r].summary !== hadSummary[i])) {
      renderSummary();
      loadEvents();
      showStatus('the run has ended: summary loaded');
    } else if (ended.length) {
      renderSummary();
      showStatus('the run has ended without a summary: it was killed');
    }
    if (ended.length) {
      // The frame at the cursor is the same request as before, but the map's HUD now says how
      // the run ended ("Run failed", "Run killed"): ask for it again.
      for (const slot of Object.values(slots)) if (slot) slot.refetch();
      viewChanged({ noHash: true });
    }
    scheduleLive();
  }

  // ------------------------------------------------------------------ bookmarks
  async function loadBookmarks() {
    try { renderBookmarks((await getJSON('/api/bookmarks')).bookmarks || []); } catch (e) { showError(e); }
  }
  function renderBookmarks(list) {
    const ul = $('bookmark-list');
    ul.innerHTML = '';
    if (!list.length) {
      ul.innerHTML = '<li class="empty">none yet: press B to bookmark this moment</li>';
      return;
    }
    for (const b of list) {
      const li = document.createElement('li');
      li.title = b.view ? `#${b.view}` : '';
      li.dataset.name = b.name;
      li.innerHTML = `<span class="bm-name">${esc(b.name)}</span><span class="bm-time">${fmtTime(Number(b.t))}</span>`;
      li.addEventListener('click', () => {
        if (b.view) applyView(b.view); else setTime(Number(b.t));
      });
      ul.appendChild(li);
    }
  }
  function openBookmarkDialog() {
    if (S.playing) play(false);
    $('bookmark-time').textContent = `at ${fmtTime(S.t)}`;
    $('bookmark-dialog').hidden = false;
    const input = $('bookmark-name');
    input.value = '';
    setTimeout(() => input.focus(), 0);
  }
  function closeDialogs() {
    $('bookmark-dialog').hidden = true;
    $('help-overlay').hidden = true;
  }
  async function saveBookmark() {
    const name = $('bookmark-name').value.trim();
    if (!name) { showError('bookmark: give it a name'); $('bookmark-name').focus(); return; }
    const body = { name: name.slice(0, 200), t: S.t, view: buildHash() };
    try {
      const r = await getJSON('/api/bookmarks', null, {
        method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body),
      });
      renderBookmarks(r.bookmarks || []);
      closeDialogs();
      showStatus(`bookmark “${name}” saved`);
    } catch (e) { showError(e); }
  }

  // ------------------------------------------------------------------ export and command line
  function setExportDefaults() {
    const a = S.info.a;
    $('export-from').value = fmtParamT(a.first_time);
    $('export-to').value = fmtParamT(a.last_time);
  }
  function exportRange() {
    const f = Number($('export-from').value), t = Number($('export-to').value);
    return { from: f, to: t, fps: Number($('export-fps').value) || 30, speed: Number($('export-speed').value) || 1 };
  }
  function commandView() {
    const v = viewParams();
    let s = ` --width ${v.width} --height ${v.height} --camera ${v.camera} --zoom ${v.zoom}`;
    if (v.center) s += ` --center ${v.center}`;
    s += ` --layers ${v.layers ? shellQuote(v.layers) : "''"}`;
    return s;
  }
  function updateCommands() {
    const a = S.info.a;
    if (!a) return;
    const path = shellQuote(a.path || 'RUN_DIR');
    const tText = Math.abs(S.t * 1000 - Math.round(S.t * 1000)) < 1e-6 ? S.t.toFixed(3) : fmtParamT(S.t);
    const b = S.info.b;
    const overlay = S.compare && S.compareMode === 'overlay' && b ? ` --overlay ${shellQuote(b.path || 'RUN_B')}` : '';
    const still = `vascsim render ${path} --still ${tText} --png view.png${commandView()}${overlay}`;
    const r = exportRange();
    const clip = `vascsim render ${path} --from ${fmtParamT(r.from)} --to ${fmtParamT(r.to)} --fps ${r.fps} --speed ${r.speed} --mp4 clip.mp4${commandView()}${overlay}`;
    $('command-still').value = still;
    $('command-clip').value = clip;
  }
  async function copyText(el) {
    const text = el.value;
    let ok = false;
    if (navigator.clipboard && window.isSecureContext) {
      try { await navigator.clipboard.writeText(text); ok = true; } catch (_) { ok = false; }
    }
    if (!ok) {
      el.focus();
      el.select();
      try { ok = document.execCommand('copy'); } catch (_) { ok = false; }
    }
    $('copy-status').textContent = ok ? 'copied' : 'selected: press Ctrl+C';
    setTimeout(() => { $('copy-status').textContent = ''; }, 2500);
  }
  let exportPoll = null;
  async function startExport() {
    const r = exportRange();
    if (!(isFinite(r.from) && isFinite(r.to)) || r.to < r.from) { showError('export: "to" must be a time at or after "from"'); return; }
    const params = Object.assign({ from: fmtParamT(r.from), to: fmtParamT(r.to), fps: r.fps, speed: r.speed }, viewParams());
    if (S.compare && S.compareMode === 'overlay') params.overlay = 'b';
    params.run = 'a';
    $('export-start').disabled = true;
    $('export-download').hidden = true;
    const bar = $('export-progress');
    bar.hidden = false;
    bar.value = 0;
    $('export-status').textContent = 'starting…';
    try {
      const { id } = await getJSON('/api/export', params, { method: 'POST' });
      $('export-status').dataset.id = id;
      pollExport(id);
    } catch (e) {
      showError(e);
      $('export-status').textContent = 'failed';
      $('export-start').disabled = false;
      bar.hidden = true;
    }
  }
  async function pollExport(id) {
    clearTimeout(exportPoll);
    let st;
    try { st = await getJSON('/api/export/status', { id }); } catch (e) {
      showError(e);
      $('export-start').disabled = false;
      return;
    }
    const bar = $('export-progress');
    bar.max = Math.max(1, st.frames_total || 1);
    bar.value = st.frames_done || 0;
    if (st.state === 'running') {
      $('export-status').textContent = `rendering ${st.frames_done} / ${st.frames_total} frames`;
      exportPoll = setTimeout(() => pollExport(id), 250);
      return;
    }
    $('export-start').disabled = false;
    if (st.state === 'done') {
      $('export-status').textContent = `${st.file || 'video'}: ${st.frames_total} frames, saved in the run directory`;
      const link = $('export-download');
      link.href = apiUrl('/api/export/file', { id });
      link.download = st.file || `export-${id}.mp4`;
      link.dataset.id = id;
      link.textContent = `Download ${st.file || 'MP4'}`;
      link.hidden = false;
    } else {
      bar.hidden = true;
      $('export-status').textContent = 'failed';
      showError(`export ${id} failed: ${st.error || 'unknown error'}`);
    }
  }

  // ------------------------------------------------------------------ keyboard
  function isTyping(el) {
    if (!el) return false;
    if (el.isContentEditable) return true;
    const tag = el.tagName;
    if (tag === 'TEXTAREA' || tag === 'SELECT') return true;
    if (tag === 'INPUT') return !['checkbox', 'radio', 'button', 'range'].includes(el.type);
    return false;
  }
  function initKeyboard() {
    document.addEventListener('keydown', (e) => {
      const dialogOpen = !$('bookmark-dialog').hidden || !$('help-overlay').hidden;
      if (e.key === 'Escape' && dialogOpen) { closeDialogs(); e.preventDefault(); return; }
      if (dialogOpen) {
        if (!$('help-overlay').hidden && (e.key === '?' || e.key === 'Enter')) { closeDialogs(); e.preventDefault(); }
        return;
      }
      if (!S.started || isTyping(e.target) || e.ctrlKey || e.metaKey || e.altKey) return;
      let handled = true;
      switch (e.key) {
        case ' ': case 'Spacebar': play(!S.playing); break;
        case 'ArrowRight': if (e.shiftKey) setTime(S.t + 1); else stepFrame(+1); break;
        case 'ArrowLeft': if (e.shiftKey) setTime(S.t - 1); else stepFrame(-1); break;
        case 'Home': setTime(S.t0); break;
        case 'End': setTime(S.t1); break;
        case '+': case '=': zoomBy(CSS_ZOOM_STEP); break;
        case '-': case '_': zoomBy(1 / CSS_ZOOM_STEP); break;
        case 'f': case 'F': fit(); break;
        case 't': case 'T': followTip(); break;
        case 'b': case 'B': openBookmarkDialog(); break;
        case '?': $('help-overlay').hidden = false; $('help-close').focus(); break;
        default: handled = false;
      }
      if (handled) e.preventDefault();
    });
  }

  // ------------------------------------------------------------------ wiring
  function initControls() {
    const on = (id, ev, f) => $(id).addEventListener(ev, f);
    on('btn-start', 'click', () => setTime(S.t0));
    on('btn-end', 'click', () => setTime(S.t1));
    on('btn-back', 'click', (e) => (e.shiftKey ? setTime(S.t - 1) : stepFrame(-1)));
    on('btn-fwd', 'click', (e) => (e.shiftKey ? setTime(S.t + 1) : stepFrame(+1)));
    on('btn-play', 'click', () => play(!S.playing));
    on('speed-select', 'change', () => { S.speed = Number($('speed-select').value) || 1; $('speed-select').blur(); });
    on('camera-select', 'change', () => { setCamera($('camera-select').value); $('camera-select').blur(); });
    on('zoom-input', 'change', () => { setZoom(Number($('zoom-input').value), true); });
    on('zoom-input', 'keydown', (e) => { if (e.key === 'Enter' || e.key === 'Escape') $('zoom-input').blur(); });
    on('btn-zoom-in', 'click', () => zoomBy(CSS_ZOOM_STEP));
    on('btn-zoom-out', 'click', () => zoomBy(1 / CSS_ZOOM_STEP));
    on('btn-fit', 'click', fit);
    on('btn-follow', 'click', followTip);
    on('compare-mode', 'change', () => {
      S.compareMode = $('compare-mode').value;
      $('compare-mode').blur();
      requestAnimationFrame(layoutMaps);
      viewChanged();
    });
    on('btn-help', 'click', () => { $('help-overlay').hidden = false; $('help-close').focus(); });
    on('help-close', 'click', closeDialogs);
    on('help-overlay', 'click', (e) => { if (e.target === $('help-overlay')) closeDialogs(); });
    on('btn-bookmark', 'click', openBookmarkDialog);
    on('bookmark-cancel', 'click', closeDialogs);
    on('bookmark-form', 'submit', (e) => { e.preventDefault(); saveBookmark(); });
    on('bookmark-dialog', 'click', (e) => { if (e.target === $('bookmark-dialog')) closeDialogs(); });
    on('btn-export-panel', 'click', () => {
      $('export-panel').scrollIntoView({ behavior: 'smooth', block: 'nearest' });
      $('export-from').focus();
    });
    on('export-start', 'click', startExport);
    for (const id of ['export-from', 'export-to', 'export-fps', 'export-speed']) {
      on(id, 'input', () => { S.exportTouched = true; updateCommands(); });
    }
    on('copy-still', 'click', () => copyText($('command-still')));
    on('copy-clip', 'click', () => copyText($('command-clip')));
    on('status-line', 'click', () => showStatus(''));
    // A mouse click leaves no focus on a button, so Space keeps meaning play/pause.
    document.addEventListener('click', (e) => {
      const b = e.target.closest && e.target.closest('button');
      if (b && e.detail > 0) b.blur();
    });
    window.addEventListener('hashchange', () => {
      const h = location.hash.replace(/^#/, '');
      if (h && h !== lastHash) applyView(h);
    });
    const ro = new ResizeObserver(() => {
      layoutMaps();
      drawTimeline();
      for (const p of plots) { p.base = null; }
      drawPlotCursors();
      clearTimeout(ro.timer);
      ro.timer = setTimeout(reloadPlots, 400);   // one bucket per pixel column at the new width
    });
    ro.observe($('maps'));
    ro.observe($('map-a'));
    ro.observe($('timeline'));
    ro.observe($('plot-list'));
  }

  function renderTitle() {
    const a = S.info.a;
    let html = `${esc(a.title || 'run')}<span class="path">${esc(a.path || '')}</span>`;
    if (S.compare) html += `<span class="vs">vs</span>${esc(S.info.b.title || 'run b')}<span class="path">${esc(S.info.b.path || '')}</span>`;
    $('run-title').innerHTML = html;
    document.title = `${a.title || 'run'} · vascsim replay`;
  }

  async function init() {
    slots.a = new Slot('a');
    initKeyboard();
    try {
      S.info.a = await getJSON('/api/run', { run: 'a' });
      S.compare = (S.info.a.runs || []).includes('b');
      if (S.compare) {
        S.info.b = await getJSON('/api/run', { run: 'b' });
        slots.b = new Slot('b');
      }
    } catch (e) {
      showError(e);
      $('hover-readout').innerHTML = '<span class="dim">the run could not be loaded</span>';
      return;
    }
    const a = S.info.a;
    S.dt = a.output_interval;
    S.layers = a.layers.filter((l) => (a.default_layers || a.layers).includes(l));
    setRange();
    S.t = S.t0;
    S.center = null;
    $('compare-field').hidden = !S.compare;
    $('compare-panel').hidden = !S.compare;
    renderTitle();
    buildLayerToggles();
    renderSummary();
    setExportDefaults();
    initControls();
    initTimeline();
    initMapInteraction(slots.a);
    if (slots.b) initMapInteraction(slots.b);
    initPlots();
    layoutMaps();
    if (location.hash.length > 1) applyView(location.hash);
    S.started = true;
    viewChanged();
    loadEvents();
    loadBookmarks();
    scheduleLive();
  }

  // ------------------------------------------------------------------ test hooks
  function blobToBase64(blob) {
    return new Promise((resolve, reject) => {
      const fr = new FileReader();
      fr.onload = () => resolve(String(fr.result).replace(/^data:[^,]*,/, ''));
      fr.onerror = () => reject(fr.error);
      fr.readAsDataURL(blob);
    });
  }
  window.vascsimReplay = {
    state: () => ({
      t: S.t, zoom: S.zoom, camera: S.camera, center: S.center ? S.center.slice() : null, layers: S.layers.slice(),
      playing: S.playing, speed: S.speed, compare: S.compare ? S.compareMode : null, range: [S.t0, S.t1],
      size: [S.size.w, S.size.h],
    }),
    currentFrameUrl: (run) => { const s = slots[run || 'a']; return s && s.shownUrl ? absUrl(s.shownUrl) : null; },
    wantedFrameUrl: (run) => absUrl(frameUrl(run || 'a')),
    currentFrameBase64: (run) => { const s = slots[run || 'a']; return s && s.blob ? blobToBase64(s.blob) : Promise.resolve(null); },
    view: (run) => { const s = slots[run || 'a']; return s && s.view ? Object.assign({}, s.view) : null; },
    ready: () => new Promise((resolve) => {
      if (S.info.a && allSettled()) resolve(true); else readyWaiters.push(() => resolve(true));
    }),
    setTime: (t) => setTime(t),
    hash: () => buildHash(),
  };

  if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', init); else init();
})();
