// The page of `morphogen breed` (docs/breed.md): one client of the JSON API.
// The plants turn in 3-D through ONE WebGL renderer on one fixed canvas
// behind the grid, drawing each cell's scene into that cell's rectangle with
// scissor/viewport (browsers allow only a few WebGL contexts per page).
// three.js r111 (Debian's libjs-three) is loaded by index.html as the global
// THREE with THREE.GLTFLoader, as in the report.

const token = new URLSearchParams(location.search).get('token') || '';
const POLL_IDLE_MS = 2000;   // another tab or a script may breed in the same session
const POLL_SEARCH_MS = 400;  // progress of "Explore around this one"
const MAX_PARENTS = 2;

const $ = (id) => document.getElementById(id);
const withToken = (url) => url + (url.includes('?') ? '&' : '?') + 'token=' + encodeURIComponent(token);

let state = null;        // the last GET /api/state (or POST answer)
let selected = [];       // ids clicked, oldest first, at most MAX_PARENTS
let busy = false;        // a request that changes the session is on its way
let viewer = null;       // the shared renderer, null without three.js/WebGL
let epoch = 0;           // counts changes made here: a poll begun before one is stale

// ---- messages -------------------------------------------------------------

function say(text, kind) {
  const m = $('message');
  m.textContent = text;
  m.className = kind || '';
  m.hidden = !text;
}

// The server answers errors as {"error": "..."}: show that sentence.
async function api(method, path, body) {
  let response;
  try {
    response = await fetch(path, {
      method,
      headers: Object.assign({ Authorization: 'Bearer ' + token },
                             body === undefined ? {} : { 'Content-Type': 'application/json' }),
      body: body === undefined ? undefined : JSON.stringify(body),
      cache: 'no-store',
    });
  } catch (e) {
    throw new Error('The server does not answer (is `morphogen breed` still running?).');
  }
  let data = null;
  try { data = await response.json(); } catch (e) { /* not JSON: said below */ }
  if (!response.ok) {
    const why = data && data.error ? data.error : response.statusText;
    throw new Error(`The server refused (${response.status}): ${why}`);
  }
  if (data === null) throw new Error(`The server's answer to ${path} is not JSON.`);
  return data;
}

// A request that changes the session: one at a time, errors shown.
async function act(method, path, body) {
  if (busy) return null;
  busy = true;
  epoch++;
  updateButtons();
  try {
    const answer = await api(method, path, body);
    say('');
    return answer;
  } catch (e) {
    say(e.message, 'error');
    return null;
  } finally {
    busy = false;
    updateButtons();
  }
}

// ---- the 3-D views --------------------------------------------------------

class Viewer {
  constructor(canvas) {
    this.renderer = new THREE.WebGLRenderer({ canvas, alpha: true, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.setScissorTest(true);
    this.renderer.outputEncoding = THREE.sRGBEncoding;
    this.scene = new THREE.Scene();
    this.scene.add(new THREE.HemisphereLight(0xeef4ff, 0x4a3a28, 0.9));
    const sun = new THREE.DirectionalLight(0xffffff, 0.8);
    sun.position.set(3, 6, 4);
    this.scene.add(sun);
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.01, 1000);
    this.loader = new THREE.GLTFLoader();
    this.models = new Map();  // id -> {root, radius, center} once loaded
    this.cells = [];          // {id, element} in grid order
    this.large = null;        // {id, renderer} while the large view is open
    this.start = performance.now();
    const loop = () => { this.draw(); requestAnimationFrame(loop); };
    requestAnimationFrame(loop);
  }

  // Loads the meshes of the grid, keeping those already loaded (the parents).
  show(cells) {
    this.cells = cells;
    const wanted = new Set(cells.map((c) => c.id));
    for (const [id, model] of this.models) {
      if (!wanted.has(id) && model.root) {
        model.root.traverse((o) => { if (o.geometry) o.geometry.dispose(); });
        this.models.delete(id);
      }
    }
    for (const cell of cells) {
      if (this.models.has(cell.id)) {
        if (this.models.get(cell.id).root) cell.element.dataset.loaded = '1';
        continue;
      }
      const model = { root: null };
      this.models.set(cell.id, model);
      this.loader.load(withToken(cell.mesh), (gltf) => {
        const root = gltf.scene;
        root.traverse((o) => {
          if (o.isMesh) {
            // COLOR_0 (colours from growth history) is the colour where the GLB has it.
            const coloured = Boolean(o.geometry.attributes.color);
            o.material = new THREE.MeshStandardMaterial({
              color: coloured ? 0xffffff : 0x6f9a4c, vertexColors: coloured, roughness: 0.8, side: THREE.DoubleSide });
          }
        });
        const box = new THREE.Box3().setFromObject(root);
        const sphere = box.getBoundingSphere(new THREE.Sphere());
        model.root = new THREE.Group();
        root.position.sub(sphere.center);  // turn about the plant's own centre
        model.root.add(root);
        model.radius = sphere.radius || 1;
        cell.element.dataset.loaded = '1';
      }, undefined, () => {
        cell.element.dataset.loaded = 'error';
        cell.element.querySelector('.view').textContent = 'the mesh did not load';
      });
    }
  }

  // The large view: its own renderer on the dialog's canvas (the dialog
  // covers the shared canvas), made once, drawing the grid's model of `id`.
  openLarge(id, canvas) {
    if (!this.largeRenderer) {
      this.largeRenderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
      this.largeRenderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
      this.largeRenderer.outputEncoding = THREE.sRGBEncoding;
    }
    this.large = { id };
  }

  closeLarge() { this.large = null; }

  // Draws `model` turning into the viewport (x, y, w, h) of renderer `r`.
  drawModel(r, model, x, y, w, h, seconds) {
    r.setViewport(x, y, w, h);
    model.root.rotation.y = seconds * 0.6;
    this.scene.add(model.root);
    this.camera.aspect = w / h;
    const distance = model.radius / Math.sin((this.camera.fov * Math.PI) / 360) * 1.05;
    this.camera.position.set(0, distance * 0.25, distance);
    this.camera.lookAt(0, 0, 0);
    this.camera.near = distance / 100;
    this.camera.far = distance * 10;
    this.camera.updateProjectionMatrix();
    r.render(this.scene, this.camera);
    this.scene.remove(model.root);
  }

  drawLarge(seconds) {
    const model = this.large && this.models.get(this.large.id);
    const r = this.largeRenderer;
    if (!model || !model.root || !r) return;
    const canvas = r.domElement;
    const width = canvas.clientWidth, height = canvas.clientHeight;
    if (!width || !height) return;
    if (canvas.width !== Math.floor(width * r.getPixelRatio()) || canvas.height !== Math.floor(height * r.getPixelRatio())) {
      r.setSize(width, height, false);
    }
    r.setClearColor(0xf1f4ee, 1);
    r.clear();
    this.drawModel(r, model, 0, 0, width, height, seconds);
    canvas.dataset.drawn = this.large.id;
  }

  draw() {
    const r = this.renderer;
    const canvas = r.domElement;
    const width = canvas.clientWidth, height = canvas.clientHeight;
    if (canvas.width !== Math.floor(width * r.getPixelRatio()) || canvas.height !== Math.floor(height * r.getPixelRatio())) {
      r.setSize(width, height, false);
    }
    r.setScissor(0, 0, width, height);
    r.setClearColor(0x000000, 0);
    r.clear();
    const top = $('grid').getBoundingClientRect().top;   // the header covers what is above
    const seconds = (performance.now() - this.start) / 1000;
    for (const cell of this.cells) {
      const model = this.models.get(cell.id);
      const rect = cell.element.querySelector('.view').getBoundingClientRect();
      if (rect.bottom < Math.max(top, 0) || rect.top > height || rect.right < 0 || rect.left > width) continue;
      const y = height - rect.bottom;
      r.setViewport(rect.left, y, rect.width, rect.height);
      r.setScissor(rect.left, y, rect.width, rect.height);
      r.setClearColor(cell.element.classList.contains('selected') ? 0xfff3c4 : 0xf1f4ee, 1);
      r.clear();
      if (!model || !model.root) continue;
      this.drawModel(r, model, rect.left, y, rect.width, rect.height, seconds);
    }
    this.drawLarge(seconds);
  }
}

function startViewer() {
  if (typeof THREE === 'undefined' || !THREE.GLTFLoader) {
    say('No 3-D view: three.js did not load (Debian package libjs-three); the thumbnails stand in.', 'warning');
    return null;
  }
  try {
    return new Viewer($('views'));
  } catch (e) {
    say('No 3-D view: this browser gave no WebGL context; the thumbnails stand in.', 'warning');
    return null;
  }
}

// ---- the grid -------------------------------------------------------------

const number = (x) => (typeof x !== 'number' ? String(x)
  : Number.isInteger(x) ? String(x) : Math.abs(x) >= 100 ? x.toFixed(0) : x.toPrecision(3));

// Tips, limbs and the first fork (as a share of the height) first: what
// tells a tree (docs/fitness-measures.md, architecture measures).
const ARCHITECTURE_KEYS = ['tips', 'limbs', 'first_fork', 'first_fork_height'];
function architectureLine(plant) {
  const m = plant.measures || {};
  const line = document.createElement('p');
  line.className = 'architecture';
  if (m.tips === undefined) {
    line.textContent = 'no architecture measures';
    return line;
  }
  const fork = m.first_fork === undefined ? '–' : m.first_fork >= 1 ? 'none' : Math.round(m.first_fork * 100) + ' %';
  line.textContent = `tips ${m.tips} · limbs ${m.limbs} · first fork ${fork}`;
  line.title = 'first fork: the lowest fork\'s height as a share of the plant\'s (none: it never forks)';
  return line;
}

function openLarge(plant) {
  const dialog = $('large');
  $('large-title').textContent = 'plant ' + plant.id;
  $('large-measures').replaceChildren(architectureLine(plant));
  const fallback = $('large-thumb');
  if (viewer) {
    fallback.hidden = true;
    $('large-view').hidden = false;
    viewer.openLarge(plant.id, $('large-view'));
  } else {
    $('large-view').hidden = true;
    fallback.hidden = false;
    fallback.src = withToken(plant.thumb);
    fallback.alt = 'plant ' + plant.id;
  }
  dialog.dataset.id = plant.id;
  if (!dialog.open) dialog.showModal();
}

function cellFor(plant, isParent) {
  const cell = document.createElement('div');
  cell.className = 'cell';
  cell.dataset.id = plant.id;
  cell.tabIndex = 0;
  cell.setAttribute('role', 'button');
  cell.setAttribute('aria-pressed', 'false');
  const view = document.createElement('div');
  view.className = 'view';
  if (!viewer) {
    const img = document.createElement('img');
    img.src = withToken(plant.thumb);
    img.alt = 'plant ' + plant.id;
    view.appendChild(img);
    cell.dataset.loaded = 'thumb';
  }
  cell.appendChild(view);
  const caption = document.createElement('div');
  caption.className = 'caption';
  const head = document.createElement('div');
  head.className = 'head';
  const name = document.createElement('span');
  name.className = 'id';
  name.textContent = plant.id;
  head.appendChild(name);
  if (isParent) {
    const badge = document.createElement('span');
    badge.className = 'badge';
    badge.textContent = 'parent';
    head.appendChild(badge);
  }
  const fitness = document.createElement('span');
  fitness.className = 'fitness';
  fitness.textContent = plant.fitness === null || plant.fitness === undefined ? 'no fitness' : 'fitness ' + number(plant.fitness);
  head.appendChild(fitness);
  const open = document.createElement('button');
  open.type = 'button';
  open.className = 'open-large';
  open.textContent = '⤢';
  open.title = 'Open this plant large';
  open.setAttribute('aria-label', 'open ' + plant.id + ' large');
  open.addEventListener('click', (e) => { e.stopPropagation(); openLarge(plant); });
  open.addEventListener('keydown', (e) => e.stopPropagation());
  head.appendChild(open);
  caption.appendChild(head);
  caption.appendChild(architectureLine(plant));
  const measures = document.createElement('dl');
  measures.className = 'measures';
  for (const [key, value] of Object.entries(plant.measures || {})) {
    if (ARCHITECTURE_KEYS.includes(key)) continue;
    const dt = document.createElement('dt');
    dt.textContent = key.replace(/_/g, ' ');
    const dd = document.createElement('dd');
    dd.textContent = number(value);
    measures.append(dt, dd);
  }
  caption.appendChild(measures);
  cell.appendChild(caption);
  cell.addEventListener('click', () => toggle(plant.id));
  cell.addEventListener('keydown', (e) => {
    if (e.key === 'Enter' || e.key === ' ') { e.preventDefault(); toggle(plant.id); }
  });
  return cell;
}

const gridKey = (s) => s.generation + ':' + s.grid.map((p) => p.id).join(',');

// Shows a state from the server; rebuilds the grid only when it changed.
function render(next) {
  const changed = !state || gridKey(state) !== gridKey(next);
  state = next;
  $('session').textContent = next.session;
  $('generation').textContent = next.generation;
  document.title = `morphogen breed · ${next.session} · generation ${next.generation}`;
  if (changed) {
    const grid = $('grid');
    const cells = next.grid.map((plant) => ({ id: plant.id, mesh: plant.mesh, element: cellFor(plant, next.chosen.includes(plant.id)) }));
    grid.replaceChildren(...cells.map((c) => c.element));
    grid.dataset.columns = Math.ceil(Math.sqrt(cells.length));
    const ids = new Set(next.grid.map((p) => p.id));
    selected = selected.filter((id) => ids.has(id));
    if (viewer) viewer.show(cells);
    $('hint').hidden = next.generation > 0;
  }
  markSelection();
  showSearch(next.search);
  updateButtons();
}

function toggle(id) {
  if (state && state.search.running) return;
  if (selected.includes(id)) selected = selected.filter((s) => s !== id);
  else {
    selected.push(id);
    if (selected.length > MAX_PARENTS) selected.shift();
  }
  $('export-result').hidden = true;
  markSelection();
  updateButtons();
}

function markSelection() {
  for (const cell of $('grid').children) {
    const on = selected.includes(cell.dataset.id);
    cell.classList.toggle('selected', on);
    cell.setAttribute('aria-pressed', on ? 'true' : 'false');
  }
}

function updateButtons() {
  const running = !!(state && state.search.running);
  const idle = !busy && !running && !!state;
  $('breed').disabled = !idle || selected.length < 1;
  $('breed').textContent = selected.length === 2 ? 'Breed (cross the two)' : 'Breed';
  $('explore').disabled = !idle || selected.length < 1;
  $('export').disabled = busy || selected.length !== 1;
  $('undo').disabled = !idle || !state.can_undo;
  $('redo').disabled = !idle || !state.can_redo;
}

// ---- the search -----------------------------------------------------------

function showSearch(search) {
  const box = $('search');
  box.hidden = !search.running;
  const bar = $('search-progress');
  bar.max = Math.max(search.total, 1);
  bar.value = Math.min(search.done, bar.max);
  $('search-text').textContent = search.message || `${search.done} of ${search.total} births`;
  if (!search.running && search.message && lastSearchRunning) say(search.message, 'info');
  lastSearchRunning = search.running;
}
let lastSearchRunning = false;

// ---- the lineage ----------------------------------------------------------

// Rows by generation, oldest at the top; in a row, a plant sits near the mean
// place of its parents (few crossing lines), edges drawn in SVG under the
// HTML thumbnails.
function drawLineage(nodes) {
  const box = $('lineage-tree');
  box.replaceChildren();
  if (nodes.length === 0) {
    box.textContent = 'Nothing chosen yet: breed once and the family tree starts here.';
    return;
  }
  const W = 104, H = 128, GAP = 16;
  const byGen = new Map();
  for (const n of nodes) {
    if (!byGen.has(n.generation)) byGen.set(n.generation, []);
    byGen.get(n.generation).push(n);
  }
  const generations = [...byGen.keys()].sort((a, b) => a - b);
  const place = new Map();  // id -> {x, y}
  let columns = 0;
  generations.forEach((g, row) => {
    const rowNodes = byGen.get(g);
    const key = (n) => {
      const xs = n.parents.filter((p) => place.has(p)).map((p) => place.get(p).x);
      return xs.length ? xs.reduce((a, b) => a + b, 0) / xs.length : -1;
    };
    rowNodes.sort((a, b) => key(a) - key(b) || (a.id < b.id ? -1 : 1));
    rowNodes.forEach((n, i) => place.set(n.id, { x: i * (W + GAP), y: row * (H + GAP * 2) }));
    columns = Math.max(columns, rowNodes.length);
  });
  const width = columns * (W + GAP), height = generations.length * (H + GAP * 2);
  const svgNS = 'http://www.w3.org/2000/svg';
  const svg = document.createElementNS(svgNS, 'svg');
  svg.setAttribute('width', width);
  svg.setAttribute('height', height);
  for (const n of nodes) {
    for (const p of n.parents) {
      if (!place.has(p)) continue;
      const a = place.get(p), b = place.get(n.id);
      const path = document.createElementNS(svgNS, 'path');
      const x1 = a.x + W / 2, y1 = a.y + H, x2 = b.x + W / 2, y2 = b.y;
      path.setAttribute('d', `M${x1},${y1} C${x1},${(y1 + y2) / 2} ${x2},${(y1 + y2) / 2} ${x2},${y2}`);
      svg.appendChild(path);
    }
  }
  const layer = document.createElement('div');
  layer.className = 'tree';
  layer.style.width = width + 'px';
  layer.style.height = height + 'px';
  layer.appendChild(svg);
  for (const n of nodes) {
    const p = place.get(n.id);
    const node = document.createElement('figure');
    node.className = 'node' + (n.chosen ? ' chosen' : '');
    node.dataset.id = n.id;
    node.style.left = p.x + 'px';
    node.style.top = p.y + 'px';
    node.style.width = W + 'px';
    const img = document.createElement('img');
    img.src = withToken(n.thumb);
    img.alt = 'plant ' + n.id;
    img.width = W - 8;
    img.height = W - 8;
    const caption = document.createElement('figcaption');
    caption.textContent = `${n.id} · gen ${n.generation}`;
    node.append(img, caption);
    layer.appendChild(node);
  }
  box.appendChild(layer);
}

async function openLineage() {
  const dialog = $('lineage');
  const data = await act('GET', '/api/lineage');
  if (!data) return;
  drawLineage(data.nodes);
  if (!dialog.open) dialog.showModal();
}

// ---- actions --------------------------------------------------------------

async function breed() {
  const parents = selected.slice();
  const next = await act('POST', '/api/breed', { parents, strength: Number($('strength').value) });
  if (next) { selected = []; render(next); }
}

async function undoRedo(which) {
  if (!state || !(which === 'undo' ? state.can_undo : state.can_redo)) return;
  const next = await act('POST', '/api/' + which);
  if (next) render(next);
}

async function exportChosen() {
  const request = { id: selected[0] };
  const height = $('export-height').value, lods = $('export-lods').value;
  if (height !== '') request.height = Number(height);
  if (lods !== '') request.lods = Number(lods);
  if ($('export-wind').checked) request.wind = true;
  if ($('export-colour').checked) request.colour = true;
  if ($('export-leaves').checked) request.leaves = true;
  const presets = $('export-wind-presets').value.split(',').map((name) => name.trim()).filter((name) => name);
  if (presets.length) request.wind_presets = presets;
  const written = await act('POST', '/api/export', request);
  if (!written) return;
  const out = $('export-result');
  out.replaceChildren(`Exported ${request.id} into the session directory ${state.session}/: `);
  for (const [kind, path] of Object.entries(written)) {
    const code = document.createElement('code');
    code.dataset.kind = kind;
    code.textContent = path;
    out.append(code, ' ');
  }
  out.hidden = false;
}

async function explore() {
  const births = Math.round(Number($('births').value));
  const next = await act('POST', '/api/explore', { parents: selected.slice(), births });
  if (next) { selected = []; render(next); schedulePoll(); }
}

async function stopSearch() {
  const next = await act('POST', '/api/explore/stop');
  if (next) render(next);
}

// ---- keeping up with the server ------------------------------------------

let pollTimer = null;
function schedulePoll() {
  clearTimeout(pollTimer);
  const wait = state && state.search.running ? POLL_SEARCH_MS : POLL_IDLE_MS;
  pollTimer = setTimeout(poll, wait);
}

async function poll() {
  if (!busy) {
    const began = epoch;
    try {
      const fresh = await api('GET', '/api/state');
      if (began === epoch && !busy) render(fresh);
      if ($('message').className === 'error' && /does not answer/.test($('message').textContent)) say('');
    } catch (e) {
      say(e.message, 'error');
    }
  }
  schedulePoll();
}

function wire() {
  $('breed').addEventListener('click', breed);
  $('undo').addEventListener('click', () => undoRedo('undo'));
  $('redo').addEventListener('click', () => undoRedo('redo'));
  $('export').addEventListener('click', exportChosen);
  $('explore').addEventListener('click', explore);
  $('stop').addEventListener('click', stopSearch);
  $('show-lineage').addEventListener('click', openLineage);
  $('close-lineage').addEventListener('click', () => $('lineage').close());
  $('close-large').addEventListener('click', () => $('large').close());
  $('large').addEventListener('close', () => { if (viewer) viewer.closeLarge(); });
  const strength = $('strength');
  strength.addEventListener('input', () => { $('strength-value').textContent = Number(strength.value).toFixed(2); });
  document.addEventListener('keydown', (e) => {
    if (!(e.ctrlKey || e.metaKey) || e.altKey) return;
    if (e.target instanceof HTMLInputElement && e.target.type !== 'range' && e.target.type !== 'checkbox') return;
    const key = e.key.toLowerCase();
    if (key === 'z' && !e.shiftKey) { e.preventDefault(); undoRedo('undo'); }
    else if ((key === 'z' && e.shiftKey) || key === 'y') { e.preventDefault(); undoRedo('redo'); }
  });
  document.addEventListener('visibilitychange', () => { if (!document.hidden) poll(); });
}

async function main() {
  wire();
  if (!token) {
    say('This address has no session token: open the address that `morphogen breed` printed.', 'error');
    return;
  }
  viewer = startViewer();
  try {
    render(await api('GET', '/api/state'));
  } catch (e) {
    say(e.message, 'error');
  }
  schedulePoll();
  document.body.dataset.ready = '1';
}

main();
