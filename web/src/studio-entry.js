// The studio page: choose bird, model and path; edit keyframes and gusts; fly; watch
// the flights side by side; download them. Talks to birdsim/studio/app.py. The viewer
// (three.js, uPlot) comes from view.js, inlined before this script (window.BirdsimViewer).
import "./studio.css";

const { Handles, Viewer, publish } = window.BirdsimViewer;

const OPTIONS = JSON.parse(document.getElementById("birdsim-options").textContent);
const KEY_COLUMNS = ["t", "x", "V", "z", "vx", "vz", "regime"];
const GUST_COLUMNS = ["t0", "duration", "wx", "wz"];
const DOWNLOADS = ["mp4", "usd", "bvh", "csv", "log", "html"];
const state = { path: null, note: "", handles: null, flock: false };

function el(tag, attrs = {}, parent = null, text = "") {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text) e.textContent = text;
  if (parent) parent.appendChild(e);
  return e;
}

function select(id, choices, parent, label, value) {
  const box = el("label", { class: "st-field" }, parent, label);
  const s = el("select", { id }, box);
  for (const [v, text] of choices) el("option", { value: v }, s, text);
  if (value != null) s.value = value;
  return s;
}

function showError(message) {
  const p = document.getElementById("error");
  p.textContent = message || "";
  p.hidden = !message;
}

async function api(url, body) {
  const r = await fetch(url, body ? { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) } : {});
  const data = await r.json().catch(() => ({ error: `${url}: HTTP ${r.status}` }));
  if (!r.ok || data.error) throw new Error(data.error || `HTTP ${r.status}`);
  return data;
}

function table(id, columns, parent) {
  const t = el("table", { id, class: "st-table" }, parent);
  const head = el("tr", {}, el("thead", {}, t));
  for (const c of columns) el("th", {}, head, c);
  el("th", {}, head, "");
  el("tbody", {}, t);
  return t;
}

function addRow(t, columns, row = {}) {
  const tr = el("tr", {}, t.tBodies[0]);
  for (const c of columns) {
    const td = el("td", {}, tr);
    const input = el("input", { "data-key": c, size: c === "regime" ? 9 : 5 }, td);
    input.value = row[c] ?? "";
  }
  const del = el("button", { type: "button", class: "st-del", title: "remove" }, el("td", {}, tr), "x");
  del.addEventListener("click", () => tr.remove());
  return tr;
}

function readRows(t) {
  return Array.from(t.tBodies[0].rows).map((tr) => {
    const row = {};
    for (const input of tr.querySelectorAll("input")) {
      const k = input.dataset.key;
      const v = input.value.trim();
      if (v === "") continue;
      row[k] = k === "regime" ? v : Number(v);
    }
    return row;
  });
}

function currentPath() {
  if (!state.path) return null;
  const path = { ...state.path, keyframe: readRows(document.getElementById("keyframes")) };
  const d = document.getElementById("duration").value.trim();
  if (d !== "") path.duration = Number(d);
  return path;
}

function fillPath(path, note) {
  state.path = path;
  const t = document.getElementById("keyframes");
  t.tBodies[0].replaceChildren();
  document.getElementById("path-note").textContent = note || "";
  document.getElementById("duration").value = path ? path.duration : "";
  if (path) for (const row of path.keyframe) addRow(t, KEY_COLUMNS, row);
}

// A flock's file gives its birds, path and model: the page's bird, gusts and open loop do
// not apply (the server refuses them), so they are disabled and not sent.
const FLOCK_FIXED = ["bird", "model", "open-loop", "add-gust"];

function setFlock(flock) {
  state.flock = flock;
  for (const id of FLOCK_FIXED) {
    const e = document.getElementById(id);
    if (e) e.disabled = flock;
  }
}

async function loadPath() {
  showError("");
  try {
    const data = await api(`/api/path?source=${encodeURIComponent(document.getElementById("source").value)}`);
    fillPath(data.path, data.note);
    setFlock(Boolean(data.flock));
  } catch (err) {
    fillPath(null, "");
    showError(err.message);
  }
}

function refX(viewer, t) {
  const d = viewer.data;
  const rt = d.reference_t;
  const r = d.reference;
  const n = rt.length;
  let k = 0;
  while (k < n - 2 && rt[k + 1] < t) k++;
  const w = Math.min(1, Math.max(0, (t - rt[k]) / (rt[k + 1] - rt[k] || 1)));
  return r[3 * k] * (1 - w) + r[3 * (k + 1)] * w;
}

function showHandles(viewer) {
  if (!state.path) return;
  const rows = readRows(document.getElementById("keyframes"));
  const h = new Handles(viewer, (index, x, z) => {
    const tr = document.getElementById("keyframes").tBodies[0].rows[index];
    if (!tr) return;
    const xi = tr.querySelector('input[data-key="x"]');
    if (xi.value.trim() !== "") xi.value = x.toFixed(3);
    tr.querySelector('input[data-key="z"]').value = z.toFixed(3);
  });
  const period = viewer.data.time_base.period;
  h.set(
    rows.map((r, index) => {
      const xFree = r.x != null;
      return { index, xFree, x: xFree ? r.x : refX(viewer, (r.t || 0) * period), z: r.z ?? 0 };
    }),
  );
  state.handles = h;
  viewer.handles = h; // for scripts and tests
}

async function fly() {
  showError("");
  const progress = document.getElementById("progress");
  const body = state.flock
    ? { label: document.getElementById("source").value }
    : {
        bird: document.getElementById("bird").value,
        model: document.getElementById("model").value,
        gusts: readRows(document.getElementById("gusts")).map((g) => GUST_COLUMNS.map((c) => g[c] ?? 0).join(":")),
        open_loop: document.getElementById("open-loop").checked,
        label: document.getElementById("source").value,
      };
  const path = currentPath();
  if (path) body.path = path;
  else body.source = document.getElementById("source").value;
  const button = document.getElementById("fly");
  button.disabled = true;
  try {
    const { job } = await api("/api/fly", body);
    let info;
    for (;;) {
      info = await api(`/api/job/${job}`);
      progress.value = info.progress;
      progress.textContent = `${Math.round(100 * info.progress)} %`;
      if (info.state !== "running") break;
      await new Promise((r) => setTimeout(r, 150));
    }
    if (info.state === "error") throw new Error(info.error);
    await openFlight(info.flight, body);
  } catch (err) {
    showError(err.message);
  } finally {
    button.disabled = false;
  }
}

const fmt = (v) => (v == null ? "n/a" : Number(v).toPrecision(3));

async function openFlight(fid, body) {
  const scene = await api(`/api/flight/${fid}/scene`);
  const box = el("div", { class: "st-flight", "data-flight": fid }, document.getElementById("flights"));
  const s = scene.summary;
  const bar = el("div", { class: "st-flight-bar" }, box);
  el(
    "span",
    { class: "st-summary" },
    bar,
    `${fid}: ${body.label} (${scene.flock ? `${scene.flock.n_birds} birds, worst bird` : body.bird || "seed"}) error RMS ${fmt(s.rms_error)} max ${fmt(s.max_error)} ${scene.units.length}` +
      (s.wingbeats_saturated ? `, saturated in ${s.wingbeats_saturated} wingbeat(s)` : ""),
  );
  for (const kind of DOWNLOADS) {
    el("a", { class: `st-download download-${kind}`, href: `/api/flight/${fid}/download/${kind}` }, bar, kind.toUpperCase());
  }
  const close = el("button", { type: "button", class: "st-close" }, bar, "close");
  const viewer = publish(new Viewer(box, scene, { width: 430, height: 300 }));
  close.addEventListener("click", () => {
    viewer.dispose();
    box.remove();
  });
  showHandles(viewer);
}

function build() {
  const root = document.getElementById("studio");
  const head = el("header", { class: "st-head" }, root);
  el("h1", {}, head, "birdsim studio");
  el("span", { class: "st-folder" }, head, `files from ${OPTIONS.folder}`);
  const side = el("aside", { class: "st-side" }, root);
  select("bird", OPTIONS.birds.map((b) => [b, b]), side, "bird", "shipped:seed-bird.toml");
  select("model", OPTIONS.models.map((m) => [m, m]), side, "model", OPTIONS.default_model);
  const src = select("source", [...OPTIONS.presets.map((p) => [p, `preset: ${p}`]), ...OPTIONS.files.map((f) => [f, f])], side, "path", "cruise");
  src.addEventListener("change", loadPath);
  el("h2", {}, side, "keyframes (wingbeats, semispans, omega s)");
  el("p", { id: "path-note", class: "st-note" }, side);
  const dl = el("label", { class: "st-field" }, side, "duration [wingbeats]");
  el("input", { id: "duration", size: 6 }, dl);
  const kt = table("keyframes", KEY_COLUMNS, side);
  el("button", { type: "button", id: "add-keyframe" }, side, "add keyframe").addEventListener("click", () => addRow(kt, KEY_COLUMNS));
  el("h2", {}, side, "gusts (wingbeats, omega s)");
  const gt = table("gusts", GUST_COLUMNS, side);
  el("button", { type: "button", id: "add-gust" }, side, "add gust").addEventListener("click", () => addRow(gt, GUST_COLUMNS, { t0: 4, duration: 1, wx: 0, wz: 0.1 }));
  const ol = el("label", { class: "st-field" }, side, "open loop ");
  el("input", { id: "open-loop", type: "checkbox" }, ol);
  el("button", { type: "button", id: "fly", class: "st-fly" }, side, "fly").addEventListener("click", fly);
  el("progress", { id: "progress", max: 1, value: 0 }, side);
  el("p", { id: "error", class: "st-error", hidden: "" }, side);
  el("main", { id: "flights", class: "st-flights" }, root);
  loadPath();
}

build();
