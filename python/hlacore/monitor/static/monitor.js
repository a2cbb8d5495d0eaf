// hlacore monitor page: receives the monitor's views over a WebSocket (hlacore/monitor/__init__.py) and
// redraws the gateway line, one table per federation, the chart and the event log. No framework, no build.
"use strict";

const WINDOW_SECONDS = 120;  // the chart's wall-clock span
const history = new Map();   // federate key -> [[wall, logical time], ...]
const colours = new Map();   // federate key -> CSS colour, stable while the federate stays
let latest = null;
let nextHue = 210;  // blue first

function colourOf(key) {
  if (!colours.has(key)) {
    let hue = nextHue % 360;
    if (hue < 30 || hue > 320) hue = (hue + 70) % 360;  // no reds: red is for the federates holding others back
    colours.set(key, `hsl(${hue}, 65%, 42%)`);
    nextHue += 137.5;  // the golden angle: neighbours differ
  }
  return colours.get(key);
}

function number(value, digits = 6) {
  if (value === null || value === undefined) return "∞";
  if (Number.isInteger(value) && Math.abs(value) < 1e9) return String(value);
  return Number(value.toPrecision(digits)).toString();
}

function bytes(n) {
  if (n === undefined || n === null) return "?";
  const units = ["B", "KiB", "MiB", "GiB"];
  let i = 0;
  while (n >= 1024 && i < units.length - 1) { n /= 1024; i++; }
  return `${n.toFixed(i ? 1 : 0)} ${units[i]}`;
}

function clock(wall) {
  return new Date(wall * 1000).toLocaleTimeString([], { hour12: false });
}

// ---- the gateway line ----
function drawGateway(view) {
  const el = document.getElementById("gateway");
  const p = view.process || {};
  const cpu = p.cpu_percent === null || p.cpu_percent === undefined ? "?" : `${p.cpu_percent.toFixed(1)} %`;
  const text = `gateway ${view.address || "?"}${view.tls ? " (TLS)" : ""} · ${view.connections ?? "?"} connection(s)` +
    ` · memory ${bytes(p.rss_bytes)} · CPU ${cpu} · pid ${p.pid ?? "?"} · ${clock(view.wall)}`;
  el.textContent = view.connected ? text : `gateway unreachable: ${view.error} (${clock(view.wall)}; last seen: ${text})`;
  el.classList.toggle("down", !view.connected);
}

// ---- one table per federation ----
const COLUMNS = [
  ["handle", "fed", (f) => f.handle],
  ["name", "name", null],
  ["time", "time", (f) => number(f.time)],
  ["lookahead", "lookahead", (f) => number(f.lookahead)],
  ["switches", "R/C", (f) => (f.regulating ? "R" : "-") + (f.constrained ? "C" : "-")],
  ["pending", "pending request", (f) => f.pending
    ? `${f.pending.request} ${number(f.pending.time)} for ${f.pending.waiting.toFixed(1)} s` : "-"],
  ["lbts", "LBTS", (f) => number(f.lbts)],
  ["queued", "TSO / RO queued", (f) => `${f.queued_tso} / ${f.queued_ro}`],
  ["backlog", "backlog memory / disk", (f) => f.backlog ? `${bytes(f.backlog.memory)} / ${bytes(f.backlog.disk)}` : "-"],
  ["grants", "grants/s", (f) => f.grants_per_second.toFixed(1)],
  ["updates", "updates/s", (f) => f.updates_per_second.toFixed(1)],
  ["state", "state", (f) => f.holding
    ? `holding back ${f.holding.federates.join(", ")} for ${f.holding.seconds.toFixed(1)} s` : ""],
];

function federationBlock(name) {
  const id = "federation-" + encodeURIComponent(name);
  let block = document.getElementById(id);
  if (block) return block;
  block = document.createElement("div");
  block.id = id;
  block.className = "federation";
  block.dataset.federation = name;
  block.innerHTML = `<h2></h2><div class="federation-meta"></div><table><thead><tr></tr></thead><tbody></tbody></table>`;
  const head = block.querySelector("thead tr");
  for (const [cls, title] of COLUMNS) {
    const th = document.createElement("th");
    th.className = cls;
    th.textContent = title;
    head.appendChild(th);
  }
  document.getElementById("federations").appendChild(block);
  return block;
}

function saveText(s) {
  if (!s) return "";
  if (s.state === "idle") return s.saves && s.saves.length ? `saves: ${s.saves.join(", ")}` : "no save";
  return `${s.state} '${s.label}'${s.answered ? `, ${s.answered.length} answered` : ""}`;
}

function drawFederation(federation) {
  const block = federationBlock(federation.name);
  block.querySelector("h2").textContent = `federation ${federation.name}`;
  const points = federation.sync_points.length ? federation.sync_points.join(", ") : "none";
  block.querySelector(".federation-meta").textContent =
    `${federation.fed} · ${federation.federates.length} federate(s) · ${federation.objects} object(s) · ` +
    `synchronization points: ${points} · ${saveText(federation.save_restore)}`;
  const body = block.querySelector("tbody");
  const rows = new Map([...body.children].map((row) => [row.dataset.key, row]));
  federation.federates.forEach((f, index) => {
    let row = rows.get(f.key);
    if (!row) {
      row = document.createElement("tr");
      row.className = "federate";
      row.dataset.key = f.key;
      row.dataset.name = f.name;
      for (const [cls] of COLUMNS) {
        const td = document.createElement("td");
        td.className = cls;
        row.appendChild(td);
      }
      const swatch = document.createElement("span");
      swatch.className = "swatch";
      swatch.style.background = colourOf(f.key);
      row.querySelector("td.name").append(swatch, document.createTextNode(f.name));
    }
    rows.delete(f.key);
    if (body.children[index] !== row) body.insertBefore(row, body.children[index] || null);
    for (const [cls, , text] of COLUMNS) {
      if (text) row.querySelector("td." + cls).textContent = text(f);
    }
    row.classList.toggle("holding", Boolean(f.holding));
    row.classList.toggle("waiting", Boolean(f.pending));
  });
  for (const gone of rows.values()) gone.remove();  // resigned or dropped: the log says which
}

function drawFederations(view) {
  const present = new Set(view.federations.map((f) => f.name));
  for (const block of [...document.querySelectorAll(".federation")]) {
    if (!present.has(block.dataset.federation)) block.remove();
  }
  view.federations.forEach(drawFederation);
}

// ---- the Federate Protocol's door: its sessions, open and lately ended ----
function sessionState(s) {
  if (s.state === "dropped") return `dropped ${s.dropped_seconds.toFixed(1)} s ago, waiting for a resume`;
  if (s.state === "ended") return `ended: ${s.reason}`;
  return s.state;
}

function drawDoor(view) {
  const door = view.fedpro;
  document.getElementById("fedpro-section").hidden = !door;
  if (!door) return;
  document.getElementById("fedpro-door").textContent = `(${door.transport} on ${door.address})`;
  const rows = door.sessions.map((s) => {
    const row = document.createElement("tr");
    row.className = "session " + s.state;
    row.dataset.session = s.id;
    const who = s.federate ? `${s.federate} of '${s.federation}'` : "not joined";
    for (const text of [s.id, who, sessionState(s), String(s.resumes), bytes(s.kept_bytes)]) {
      const td = document.createElement("td");
      td.textContent = text;
      row.appendChild(td);
    }
    return row;
  });
  document.querySelector("#fedpro tbody").replaceChildren(...rows.reverse());  // the newest first
}

// ---- the chart: each federate's logical time against wall-clock time ----
function record(view) {
  const present = new Set();
  for (const federation of view.federations) {
    for (const f of federation.federates) {
      present.add(f.key);
      if (!history.has(f.key)) history.set(f.key, []);
      history.get(f.key).push([view.wall, f.time]);
    }
  }
  for (const key of [...history.keys()]) {
    if (view.connected && !present.has(key)) { history.delete(key); colours.delete(key); }
  }
  for (const points of history.values()) {
    while (points.length && points[0][0] < view.wall - WINDOW_SECONDS) points.shift();
  }
}

function drawChart() {
  const canvas = document.getElementById("chart");
  const ratio = window.devicePixelRatio || 1;
  const width = canvas.clientWidth, height = canvas.clientHeight;
  if (canvas.width !== width * ratio) { canvas.width = width * ratio; canvas.height = height * ratio; }
  const ctx = canvas.getContext("2d");
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.clearRect(0, 0, width, height);
  if (!latest) return;
  const now = latest.wall, left = 60, right = width - 10, top = 10, bottom = height - 24;
  let low = Infinity, high = -Infinity;
  for (const points of history.values()) {
    for (const [, t] of points) { low = Math.min(low, t); high = Math.max(high, t); }
  }
  if (!isFinite(low)) return;
  if (high - low < 1e-9) { low -= 1; high += 1; }
  const x = (wall) => left + (right - left) * (1 - (now - wall) / WINDOW_SECONDS);
  const y = (t) => bottom - (bottom - top) * (t - low) / (high - low);
  ctx.strokeStyle = "#c8ccd4"; ctx.fillStyle = "#556"; ctx.lineWidth = 1; ctx.font = "11px system-ui";
  ctx.beginPath(); ctx.moveTo(left, top); ctx.lineTo(left, bottom); ctx.lineTo(right, bottom); ctx.stroke();
  for (let s = 0; s <= WINDOW_SECONDS; s += 30) ctx.fillText(s ? `-${s} s` : "now", x(now - s) - 12, height - 8);
  ctx.fillText(number(high, 5), 4, top + 8);
  ctx.fillText(number(low, 5), 4, bottom);
  const holding = new Set();
  for (const federation of latest.federations) {
    for (const f of federation.federates) if (f.holding) holding.add(f.key);
  }
  const keys = [...history.keys()].sort((a, b) => holding.has(a) - holding.has(b));  // highlighted on top
  for (const key of keys) {
    const points = history.get(key);
    ctx.strokeStyle = holding.has(key) ? "#d32f2f" : colourOf(key);
    ctx.lineWidth = holding.has(key) ? 3 : 1.5;
    ctx.beginPath();
    points.forEach(([wall, t], i) => (i ? ctx.lineTo(x(wall), y(t)) : ctx.moveTo(x(wall), y(t))));
    ctx.stroke();
  }
}

// ---- the event log ----
function addEvents(events) {
  const log = document.getElementById("log");
  for (const e of events) {
    const li = document.createElement("li");
    li.className = e.kind;
    li.dataset.sequence = e.sequence;
    const when = document.createElement("time");
    when.textContent = clock(e.time);
    const who = e.federate ? `federate ${e.federate} '${e.name}' of '${e.federation}'` : `federation '${e.federation}'`;
    li.append(when, document.createTextNode(`${who} ${e.kind}${e.reason ? ": " + e.reason : ""}`));
    log.insertBefore(li, log.firstChild);
  }
  while (log.children.length > 1000) log.lastChild.remove();
}

// ---- the connection ----
function receive(message) {
  if (message.type === "hello") {
    history.clear();
    for (const [key, points] of Object.entries(message.history)) history.set(key, points);
    document.getElementById("log").replaceChildren();
    addEvents(message.events);
    if (message.latest) show(message.latest, false);
  } else {
    show(message, true);
  }
}

function show(view, fresh) {
  latest = view;
  window.hlacoreViews = (window.hlacoreViews || 0) + 1;  // views drawn: what tests/system/test_monitor.py counts
  if (fresh) record(view);
  drawGateway(view);
  drawFederations(view);
  drawDoor(view);
  if (fresh) addEvents(view.events);
  drawChart();
}

function connect() {
  const socket = new WebSocket(`${location.protocol === "https:" ? "wss" : "ws"}://${location.host}/ws`);
  socket.onmessage = (event) => receive(JSON.parse(event.data));
  socket.onclose = () => {
    const el = document.getElementById("gateway");
    el.textContent = "the monitor is not answering; retrying…";
    el.classList.add("down");
    setTimeout(connect, 1000);
  };
}

window.addEventListener("resize", drawChart);
document.getElementById("window").textContent = WINDOW_SECONDS;
connect();
