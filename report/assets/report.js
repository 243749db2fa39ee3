// The morphogen report page: reads window.MORPHOGEN_REPORT (data.js, written
// by `morphogen report`) and draws the summary, plots, viewers, ancestry,
// archive and contact sheet. Classic script, no modules and no fetch, so the
// page works from file:// with no network. Meshes come as base64 GLB in
// scripts that call morphogenMesh(key, data) when loaded on demand.
(function () {
  'use strict';
  var R = window.MORPHOGEN_REPORT;
  var $ = function (id) { return document.getElementById(id); };
  // Where the page stands, for people and for the browser tests.
  var status = window.morphogenStatus = { plots: 0, viewer: 'pending', growth: 'pending', errors: [] };

  function el(tag, attrs, text) {
    var e = document.createElement(tag);
    for (var k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
  }
  function fmt(v, digits) {
    if (v === null || v === undefined) return '–';
    if (typeof v !== 'number') return String(v);
    if (Number.isInteger(v) && Math.abs(v) < 1e15) return String(v);
    var a = Math.abs(v);
    if (a !== 0 && (a >= 1e6 || a < 1e-3)) return v.toExponential((digits || 4) - 1);
    return String(+v.toPrecision(digits || 4));
  }
  function duration(s) {
    if (s === null || s === undefined) return '–';
    var h = Math.floor(s / 3600), m = Math.floor((s % 3600) / 60), sec = s % 60;
    return (h ? h + ' h ' : '') + (h || m ? m + ' min ' : '') + sec.toFixed(h || m ? 0 : 2) + ' s';
  }

  var tooltip = $('tooltip');
  function showTip(text, x, y) {
    tooltip.textContent = text;
    tooltip.hidden = false;
    var w = tooltip.offsetWidth;
    tooltip.style.left = Math.min(x + 14, window.innerWidth - w - 8) + 'px';
    tooltip.style.top = (y + 14) + 'px';
  }
  function hideTip() { tooltip.hidden = true; }

  // ---------- the run at a glance ----------
  function glance() {
    var runName = R.name || 'run';
    document.title = runName + ' — morphogen report';
    $('title').textContent = runName;
    // The best's skeleton measures (docs/fitness-measures.md "Architecture measures") in one line.
    function architectureText(a) {
      var limbs = a.limb_lengths.map(function (l, i) { return fmt(l, 3) + '/' + fmt(a.limb_thicknesses[i], 3); });
      return a.tips + ' tips, ' + a.limbs + ' limbs' + (limbs.length ? ' (length/thickness ' + limbs.join(', ') + ')' : '') +
        ', first fork at ' + fmt(a.first_fork_height, 3) + ', Strahler ' + a.strahler +
        ', solidity ' + (a.solidity === null ? 'none (open mesh)' : fmt(a.solidity, 3));
    }
    var complete = R.generations !== null && R.generations >= R.target_generations;
    $('subtitle').textContent = (R.algorithm === 'map_elites' ? 'MAP-Elites' : 'steady-state GA') + ' · ' +
      R.run_dir + (complete ? '' : ' · in progress or stopped');
    var cfg = R.config || {};
    var best = R.best;
    var rows = [
      ['run directory', R.run_dir],
      ['algorithm', R.algorithm === 'map_elites' ? 'MAP-Elites' : 'steady-state GA'],
      ['fitness', cfg.fitness ? cfg.fitness.type : '–'],
      ['seed', fmt(R.seed)],
      ['population', fmt(R.population)],
      ['generations', (R.generations === null ? 'none yet' : fmt(R.generations)) + ' of ' + fmt(R.target_generations) +
        (complete ? '' : ' (not finished: in progress or stopped; resume continues it)')],
      ['births', fmt(R.births) + (R.checkpoint_births !== R.births ? ' (' + fmt(R.checkpoint_births) + ' at the last checkpoint)' : '')],
      ['run time', duration(R.elapsed_s)],
      ['best fitness', best ? fmt(best.fitness, 6) : 'no valid individual yet'],
      ['best individual', best ? 'id ' + best.id + ', born in generation ' + best.generation + ', ' +
        fmt(best.vertices) + ' vertices, parents ' + (best.parent1 === null ? 'none (initial population)' :
        best.parent1 + (best.parent2 === null ? '' : ' × ' + best.parent2)) : '–'],
      ['best architecture', best && best.architecture ? architectureText(best.architecture) : '–']
    ];
    var table = $('glance-table');
    rows.forEach(function (r) {
      var tr = el('tr');
      tr.appendChild(el('td', {}, r[0]));
      tr.appendChild(el('td', {}, r[1]));
      table.appendChild(tr);
    });
    $('config').textContent = JSON.stringify(R.config, null, 2);
    (R.notes || []).forEach(function (n) { $('notes').appendChild(el('li', {}, n)); });
  }

  // ---------- plots ----------
  function niceTicks(lo, hi, count) {
    if (!(hi > lo)) { hi = lo + 1; lo = lo - 1; }
    var raw = (hi - lo) / count, mag = Math.pow(10, Math.floor(Math.log10(raw)));
    var step = [1, 2, 5, 10].map(function (m) { return m * mag; }).find(function (s) { return s >= raw; });
    var ticks = [], first = Math.floor(lo / step + 1e-9) * step, last = Math.ceil(hi / step - 1e-9) * step;
    for (var t = first; t <= last + step * 1e-9; t += step) ticks.push(+t.toPrecision(12));
    return { lo: first, hi: last, ticks: ticks };
  }

  // A line chart of `series` ({name, color, values}) over xs, with axes,
  // a unit on y, a legend and the values of the nearest generation on hover.
  function chart(title, unit, xs, series, fromZero) {
    var box = el('div', { 'class': 'plot' });
    box.appendChild(el('h3', {}, title));
    var W = 420, H = 240, dpr = window.devicePixelRatio || 1;
    var canvas = el('canvas', { width: W * dpr, height: H * dpr, 'class': 'chart', 'data-title': title });
    canvas.style.width = W + 'px';
    canvas.style.height = H + 'px';
    box.appendChild(canvas);
    var legend = el('div', { 'class': 'legend' });
    series.forEach(function (s) {
      var span = el('span');
      var swatch = el('i');
      swatch.style.background = s.color;
      span.appendChild(swatch);
      span.appendChild(document.createTextNode(s.name));
      legend.appendChild(span);
    });
    box.appendChild(legend);
    $('plot-grid').appendChild(box);

    var L = 64, Rm = 12, T = 10, B = 38;
    var ys = [];
    series.forEach(function (s) { s.values.forEach(function (v) { if (v !== null && isFinite(v)) ys.push(v); }); });
    var xr = niceTicks(xs.length ? Math.min.apply(null, xs) : 0, xs.length ? Math.max.apply(null, xs) : 1, 6);
    if (fromZero) ys.push(0, 1);  // counts and rates: the axis starts at 0
    var yr = niceTicks(ys.length ? Math.min.apply(null, ys) : 0, ys.length ? Math.max.apply(null, ys) : 1, 5);
    xr.ticks = xr.ticks.filter(function (t) { return Number.isInteger(t); });
    function px(x) { return L + (x - xr.lo) / (xr.hi - xr.lo) * (W - L - Rm); }
    function py(y) { return T + (1 - (y - yr.lo) / (yr.hi - yr.lo)) * (H - T - B); }
    var ctx = canvas.getContext('2d');

    function draw(hover) {
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      ctx.clearRect(0, 0, W, H);
      ctx.font = '11px system-ui, sans-serif';
      ctx.strokeStyle = '#e4e8eb';
      ctx.fillStyle = '#57606a';
      ctx.lineWidth = 1;
      ctx.textAlign = 'right';
      ctx.textBaseline = 'middle';
      yr.ticks.forEach(function (t) {
        ctx.beginPath(); ctx.moveTo(L, py(t)); ctx.lineTo(W - Rm, py(t)); ctx.stroke();
        ctx.fillText(fmt(t), L - 5, py(t));
      });
      ctx.textAlign = 'center';
      ctx.textBaseline = 'top';
      xr.ticks.forEach(function (t) { ctx.fillText(fmt(t), px(t), H - B + 5); });
      ctx.fillText('generation', L + (W - L - Rm) / 2, H - 15);
      ctx.save();
      ctx.translate(12, T + (H - T - B) / 2);
      ctx.rotate(-Math.PI / 2);
      ctx.fillText(unit, 0, -6);
      ctx.restore();
      ctx.strokeStyle = '#8c959f';
      ctx.beginPath(); ctx.moveTo(L, T); ctx.lineTo(L, H - B); ctx.lineTo(W - Rm, H - B); ctx.stroke();
      series.forEach(function (s) {
        ctx.strokeStyle = s.color;
        ctx.fillStyle = s.color;
        ctx.lineWidth = 1.6;
        ctx.beginPath();
        var pen = false;
        s.values.forEach(function (v, i) {
          if (v === null || !isFinite(v)) { pen = false; return; }
          if (pen) ctx.lineTo(px(xs[i]), py(v)); else ctx.moveTo(px(xs[i]), py(v));
          pen = true;
        });
        ctx.stroke();
        if (xs.length === 1 && s.values[0] !== null) { ctx.beginPath(); ctx.arc(px(xs[0]), py(s.values[0]), 3, 0, 7); ctx.fill(); }
      });
      if (hover !== null) {
        ctx.strokeStyle = '#24292f';
        ctx.lineWidth = 1;
        ctx.beginPath(); ctx.moveTo(px(xs[hover]), T); ctx.lineTo(px(xs[hover]), H - B); ctx.stroke();
        series.forEach(function (s) {
          var v = s.values[hover];
          if (v === null || !isFinite(v)) return;
          ctx.fillStyle = s.color;
          ctx.beginPath(); ctx.arc(px(xs[hover]), py(v), 3.5, 0, 7); ctx.fill();
        });
      }
    }
    draw(null);
    canvas.addEventListener('mousemove', function (ev) {
      if (!xs.length) return;
      var rect = canvas.getBoundingClientRect();
      var x = xr.lo + (ev.clientX - rect.left - L) / (W - L - Rm) * (xr.hi - xr.lo);
      var best = 0;
      xs.forEach(function (g, i) { if (Math.abs(g - x) < Math.abs(xs[best] - x)) best = i; });
      draw(best);
      showTip('generation ' + xs[best] + '\n' + series.map(function (s) {
        return s.name + ': ' + fmt(s.values[best], 6) + (unit.indexOf('fitness') === 0 ? '' : ' ' + unit);
      }).join('\n'), ev.clientX, ev.clientY);
    });
    canvas.addEventListener('mouseleave', function () { draw(null); hideTip(); });
    status.plots++;
  }

  function plots() {
    var h = R.history.columns;
    var xs = h.generation.map(function (g) { return g === null ? 0 : g; });
    var fitnessUnit = 'fitness (' + ((R.config.fitness && R.config.fitness.type) || 'score') + ')';
    chart(R.algorithm === 'map_elites' ? 'Fitness of the elites' : 'Fitness of the population', fitnessUnit, xs, [
      { name: 'best', color: '#1a7f37', values: h.best },
      { name: 'mean', color: '#0969da', values: h.mean },
      { name: 'median', color: '#8250df', values: h.median },
      { name: 'worst', color: '#cf222e', values: h.worst }]);
    chart('Mean vertices', 'vertices', xs, [{ name: 'mean vertices', color: '#bf8700', values: h.mean_vertices }]);
    chart('Invalid births', 'births per generation', xs, [{ name: 'invalid births', color: '#cf222e', values: h.invalid }], true);
    chart('Speed', 'births / s', xs, [{ name: 'births per second', color: '#0969da', values: h.births_per_s }], true);
    if (h.coverage) chart('Archive coverage', 'fraction of cells', xs, [{ name: 'coverage', color: '#1a7f37', values: h.coverage }], true);
    if (h.qd_score) chart('QD score', 'sum of fitness − offset', xs, [{ name: 'QD score', color: '#8250df', values: h.qd_score }]);
  }

  // ---------- meshes, loaded on demand ----------
  var meshes = {}, waiting = {};
  window.morphogenMesh = function (key, data) {
    var text = atob(data), bytes = new Uint8Array(text.length);
    for (var i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
    meshes[key] = bytes.buffer;
    (waiting[key] || []).forEach(function (w) { w.resolve(bytes.buffer); });
    delete waiting[key];
  };
  function loadMesh(key, src) {
    if (meshes[key]) return Promise.resolve(meshes[key]);
    return new Promise(function (resolve, reject) {
      var first = !waiting[key];
      (waiting[key] = waiting[key] || []).push({ resolve: resolve, reject: reject });
      if (!first) return;
      var script = el('script', { src: src });
      script.onerror = function () {
        (waiting[key] || []).forEach(function (w) { w.reject(new Error('cannot load ' + src)); });
        delete waiting[key];
      };
      document.head.appendChild(script);
    });
  }

  // ---------- 3-D viewers ----------
  function Viewer(canvas) {
    this.canvas = canvas;
    this.renderer = new THREE.WebGLRenderer({ canvas: canvas, antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setSize(canvas.clientWidth, canvas.clientHeight, false);
    this.renderer.outputEncoding = THREE.sRGBEncoding;
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xeef1f3);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x667755, 0.75));
    var sun = new THREE.DirectionalLight(0xffffff, 0.8);
    sun.position.set(3, 10, 6);
    this.scene.add(sun);
    this.camera = new THREE.PerspectiveCamera(35, canvas.clientWidth / canvas.clientHeight, 0.01, 1e5);
    this.camera.position.set(1, 0.8, 1.6);
    this.controls = new THREE.OrbitControls(this.camera, canvas);
    this.controls.enableDamping = true;
    this.clock = new THREE.Clock();
    this.mixer = null;
    this.playing = true;
    this.content = null;
    this.ground = null;
    this.levels = [];  // {name, object, triangles} of the shown plant's LOD nodes, LOD0 first
    this.lod = 0;
    this.hasWind = false;
    // Shared by every swaying material (docs/wind.md, "Wind data").
    this.wind = { windTime: { value: 0 }, windOn: { value: 0 }, windAmp: { value: 0 }, windFlutter: { value: 0 },
      windDir: { value: new THREE.Vector3(1, 0, 0) } };
    this.swaying = false;
    var self = this;
    (function loop() {
      requestAnimationFrame(loop);
      var dt = self.clock.getDelta();
      if (self.mixer && self.playing) {
        self.mixer.update(dt);
        self.hideScaledAway();
        if (self.onTime) self.onTime(self.mixer.time);
      }
      if (self.swaying) self.wind.windTime.value += dt;
      self.controls.update();
      self.renderer.render(self.scene, self.camera);
      if (self.onFrame) self.onFrame();
    })();
  }

  // The sway of docs/wind.md ("Wind data") in the vertex shader:
  //   p' = p + A·bend·(0.5 + 0.5·sin(ω t))·W + F·flutter·(1 − stiffness)·sin(ω_f t + 2π·phase)·n
  // with ω = 2π·0.3 s⁻¹, ω_f = 2π·2 s⁻¹; GLTFLoader names the glTF attribute
  // _WIND "_wind" (unknown attributes are lower-cased). windOn 0 leaves the
  // mesh at rest.
  var SWAY_DECLARATIONS = [
    'attribute vec4 _wind;',
    'uniform float windTime;', 'uniform float windOn;', 'uniform float windAmp;', 'uniform float windFlutter;',
    'uniform vec3 windDir;'].join('\n');
  var SWAY_VERTEX = [
    'transformed += windOn * windAmp * _wind.x * (0.5 + 0.5 * sin(6.2831853 * 0.3 * windTime)) * windDir;',
    'transformed += windOn * windFlutter * _wind.y * (1.0 - _wind.w) *',
    '  sin(6.2831853 * 2.0 * windTime + 6.2831853 * _wind.z) * normal;'].join('\n');
  function swayingMaterial(material, uniforms) {
    var m = material.clone();
    m.onBeforeCompile = function (shader) {
      for (var k in uniforms) shader.uniforms[k] = uniforms[k];
      shader.vertexShader = shader.vertexShader
        .replace('#include <common>', '#include <common>\n' + SWAY_DECLARATIONS)
        .replace('#include <begin_vertex>', '#include <begin_vertex>\n' + SWAY_VERTEX);
    };
    return m;
  }
  function triangleCount(object) {
    var n = 0;
    object.traverse(function (o) {
      if (!o.isMesh) return;
      var g = o.geometry;
      n += (g.index ? g.index.count : g.attributes.position.count) / 3;
    });
    return n;
  }
  // The shown plant's levels of detail (nodes named plant_<id>_LOD<i>) and
  // its wind data: meshes with a _WIND attribute get the swaying material.
  Viewer.prototype.prepare = function (root, height) {
    var self = this, levels = [];
    self.hasWind = false;
    root.traverse(function (o) {
      var m = /_LOD(\d+)$/.exec(o.name || '');
      if (m) levels.push({ index: +m[1], name: o.name, object: o, triangles: triangleCount(o) });
      if (o.isMesh && o.geometry.attributes._wind) {
        o.material = swayingMaterial(o.material, self.wind);
        o.frustumCulled = false;  // the sway leaves the rest pose's bounds
        self.hasWind = true;
      }
    });
    levels.sort(function (a, b) { return a.index - b.index; });
    self.levels = levels;
    // What the viewer uses for A and F (metres at the farthest tip): 8 % and
    // 1 % of the plant's height, so every plant sways visibly at any size.
    self.wind.windAmp.value = 0.08 * height;
    self.wind.windFlutter.value = 0.01 * height;
    self.setLod(Math.min(self.lod, Math.max(0, levels.length - 1)));
  };
  // The canvas rows (CSS pixels from its top) of the plant's top and foot.
  Viewer.prototype.plantRows = function () {
    var box = this.box, centre = box.getCenter(new THREE.Vector3()), camera = this.camera, h = this.canvas.clientHeight;
    camera.updateMatrixWorld();
    function row(y) { return (1 - new THREE.Vector3(centre.x, y, centre.z).project(camera).y) / 2 * h; }
    return { top: row(box.max.y), foot: row(box.min.y) };
  };
  Viewer.prototype.setLod = function (i) {
    this.lod = i;
    this.levels.forEach(function (l, j) { l.object.visible = j === i; });
  };
  Viewer.prototype.setSway = function (on) {
    this.swaying = on;
    this.wind.windOn.value = on ? 1 : 0;
  };
  // Frames of a growth animation are hidden by scale 0 (STEP keys); three.js
  // cannot invert a zero scale's normal matrix (a console warning each
  // frame), so such nodes are made invisible instead of drawn.
  Viewer.prototype.hideScaledAway = function () {
    if (!this.content) return;
    this.content.traverse(function (o) {
      o.visible = o.scale.x !== 0 || o.scale.y !== 0 || o.scale.z !== 0;
    });
  };
  // Shows a GLB (ArrayBuffer); animations in it play in a loop. The camera
  // keeps its direction and is moved to frame the new mesh.
  Viewer.prototype.show = function (buffer) {
    var self = this;
    return new Promise(function (resolve, reject) {
      new THREE.GLTFLoader().parse(buffer, '', function (gltf) {
        if (self.content) self.scene.remove(self.content);
        if (self.ground) self.scene.remove(self.ground);
        self.content = gltf.scene;
        self.scene.add(gltf.scene);
        // All frames of an animation together (scale keys aside) bound the view.
        var box = new THREE.Box3();
        gltf.scene.updateMatrixWorld(true);
        gltf.scene.traverse(function (o) {
          if (!o.isMesh) return;
          o.geometry.computeBoundingBox();
          box.union(o.geometry.boundingBox.clone().applyMatrix4(o.parent ? o.parent.matrixWorld : new THREE.Matrix4()));
        });
        if (box.isEmpty()) box.set(new THREE.Vector3(-1, 0, -1), new THREE.Vector3(1, 1, 1));
        var size = box.getSize(new THREE.Vector3()), centre = box.getCenter(new THREE.Vector3());
        var radius = Math.max(size.length() / 2, 1e-3);
        self.ground = new THREE.GridHelper(radius * 4, 20, 0xa0a8b0, 0xd0d6dc);
        self.ground.position.set(centre.x, Math.min(0, box.min.y), centre.z);
        self.scene.add(self.ground);
        var dir = self.camera.position.clone().sub(self.controls.target).normalize();
        self.controls.target.copy(centre);
        self.camera.position.copy(centre).addScaledVector(dir, radius / Math.sin(self.camera.fov * Math.PI / 360) * 1.05);
        self.camera.near = radius / 100;
        self.camera.far = radius * 100;
        self.camera.updateProjectionMatrix();
        self.mixer = null;
        if (gltf.animations && gltf.animations.length) {
          self.mixer = new THREE.AnimationMixer(gltf.scene);
          gltf.animations.forEach(function (clip) { self.mixer.clipAction(clip).play(); });
          self.mixer.update(0);
        }
        self.hideScaledAway();
        self.box = box;
        self.prepare(gltf.scene, size.y);
        resolve(gltf);
      }, function (error) { reject(error instanceof Error ? error : new Error(String(error && error.message || error))); });
    });
  };

  function message(id, text) { var m = $(id); m.textContent = text; m.hidden = !text; }

  var viewer = null;
  // The sway toggle and the level selector follow what the shown plant has.
  function plantControls() {
    var sway = $('sway'), lod = $('lod'), levels = viewer.levels;
    sway.disabled = !viewer.hasWind;
    viewer.setSway(sway.checked && viewer.hasWind);
    while (lod.firstChild) lod.removeChild(lod.firstChild);
    (levels.length ? levels : [{ index: 0 }]).forEach(function (l, i) {
      lod.appendChild(el('option', { value: i }, 'LOD' + l.index));
    });
    lod.disabled = levels.length < 2;
    lod.value = viewer.lod;
    var triangles = levels.length ? levels[viewer.lod].triangles : triangleCount(viewer.content);
    $('lod-label').textContent = fmt(triangles) + ' triangles' + (levels.length ? ' (of ' + fmt(levels[0].triangles) + ' at LOD0)' : '') +
      (viewer.hasWind ? '' : ' · no wind data');
    status.sway = viewer.hasWind ? (viewer.swaying ? 'on' : 'off') : 'none';
    status.lods = levels.length;
    status.lod = viewer.lod;
    status.lodTriangles = levels.map(function (l) { return l.triangles; });
    status.triangles = triangles;
    status.plantRows = viewer.plantRows();
  }
  function showInViewer(key, src, label) {
    if (!viewer) return Promise.resolve();
    $('gen-label').textContent = label + ' (loading)';
    return loadMesh(key, src).then(function (buffer) { return viewer.show(buffer); }).then(function () {
      $('gen-label').textContent = label;
      plantControls();
      status.viewer = 'shown';
      status.shown = key;
    }).catch(function (e) {
      $('gen-label').textContent = label;
      message('viewer-message', 'cannot show ' + label + ': ' + e.message);
      status.viewer = 'failed';
      console.error(e);
    });
  }
  function showGeneration(g) {
    var m = R.meshes.find(function (x) { return x.generation === g; });
    if (!m) return Promise.resolve();
    $('gen-slider').value = R.meshes.indexOf(m);
    return showInViewer(m.key, m.script, 'generation ' + g + ', best ' + fmt(m.fitness, 6));
  }
  function viewers() {
    if (!R.three || typeof THREE === 'undefined' || !THREE.GLTFLoader || !THREE.OrbitControls) {
      message('viewer-message', 'No 3-D viewer: three.js was not found when the report was written (Debian package libjs-three).');
      message('growth-message', 'No 3-D viewer.');
      status.viewer = status.growth = 'none';
      return;
    }
    viewer = new Viewer($('viewer'));
    viewer.onFrame = function () {  // for people reading the status and for the browser tests
      status.drawnTriangles = viewer.renderer.info.render.triangles;
      status.swayTime = viewer.wind.windTime.value;
    };
    $('sway').addEventListener('change', function () { plantControls(); });
    $('lod').addEventListener('change', function () {
      viewer.setLod(+$('lod').value);
      plantControls();
    });
    var slider = $('gen-slider');
    slider.max = Math.max(0, R.meshes.length - 1);
    slider.disabled = R.meshes.length < 2;
    slider.addEventListener('input', function () {
      var m = R.meshes[+slider.value];
      if (m) showInViewer(m.key, m.script, 'generation ' + m.generation + ', best ' + fmt(m.fitness, 6));
    });
    var bestButton = $('show-best');
    bestButton.disabled = !(R.best && R.best.script);
    bestButton.addEventListener('click', function () {
      showInViewer('best', R.best.script, 'final best: id ' + R.best.id + ', fitness ' + fmt(R.best.fitness, 6));
    });
    if (R.meshes.length) showGeneration(R.meshes[R.meshes.length - 1].generation);
    else if (R.best && R.best.script) {
      message('viewer-message', 'No exported generations (best/gen_NNNN.glb): showing the final best.');
      bestButton.click();
    } else {
      message('viewer-message', 'Nothing to show: no exported generations and no best yet.');
      status.viewer = 'none';
    }

    if (!R.animation) {
      message('growth-message', 'No growth animation in this report' +
        ((R.notes || []).filter(function (n) { return n.indexOf('animation') >= 0; }).map(function (n) { return ': ' + n; })[0] || '.'));
      $('play').disabled = true;
      status.growth = 'none';
      return;
    }
    var growth = new Viewer($('growth'));
    growth.onTime = function (t) { status.growthTime = t; };
    $('play').addEventListener('click', function () {
      growth.playing = !growth.playing;
      $('play').textContent = growth.playing ? 'pause' : 'play';
    });
    loadMesh('growth', R.animation.script).then(function (buffer) { return growth.show(buffer); }).then(function (gltf) {
      var clip = gltf.animations[0];
      $('growth-label').textContent = R.animation.frames + ' frames' + (clip ? ', ' + clip.duration.toFixed(1) + ' s loop' : '');
      status.growth = gltf.animations.length ? 'playing' : 'still';
    }).catch(function (e) {
      message('growth-message', 'cannot play the growth: ' + e.message);
      status.growth = 'failed';
      console.error(e);
    });
  }

  // ---------- ancestry ----------
  function ancestry() {
    var line = R.ancestry || [];
    if (!line.length) {
      $('ancestry-intro').textContent = R.best ? 'lineage.csv does not reach the best individual.' : 'No valid individual yet.';
      return;
    }
    $('ancestry-intro').textContent = 'The final best (id ' + line[0].id + ') and its first parents, back to the initial population (' +
      line.length + ' individuals). Where an ancestor\'s generation was exported, the picture is that generation\'s best; ' +
      'click such a row to open it in the viewer.';
    var table = $('ancestry');
    var head = el('tr');
    ['generation', 'id (birth)', 'fitness', 'parents', 'best of its generation'].forEach(function (t) { head.appendChild(el('th', {}, t)); });
    table.appendChild(head);
    line.forEach(function (a) {
      var tr = el('tr');
      tr.appendChild(el('td', {}, a.generation));
      tr.appendChild(el('td', {}, a.id));
      tr.appendChild(el('td', {}, a.fitness === null ? 'invalid' : fmt(a.fitness, 6)));
      tr.appendChild(el('td', {}, a.parent1 === null ? 'initial' : a.parent1 + (a.parent2 === null ? '' : ' × ' + a.parent2)));
      var pic = el('td');
      if (a.thumb) {
        pic.appendChild(el('img', { src: a.thumb, alt: 'best of generation ' + a.generation, loading: 'lazy' }));
        tr.className = 'exported';
        tr.addEventListener('click', function () {
          showGeneration(a.generation);
          $('viewer-section').scrollIntoView({ behavior: 'smooth' });
        });
      } else {
        pic.textContent = '–';
      }
      tr.appendChild(pic);
      table.appendChild(tr);
    });
  }

  // ---------- MAP-Elites archive ----------
  function heat(t) {  // blue (low) .. green .. yellow (high)
    t = Math.max(0, Math.min(1, t));
    return 'rgb(' + Math.round(40 + 215 * t * t) + ',' + Math.round(50 + 180 * t) + ',' + Math.round(150 * (1 - t) + 30) + ')';
  }
  function elites() {
    var E = R.elites;
    if (!E) return;
    $('elites-section').hidden = false;
    $('elites-link').hidden = false;
    var D = E.descriptors;
    $('elites-intro').textContent = E.cells.length + ' of ' + E.total_cells + ' cells occupied (' + E.kind + ' archive). ' +
      'Colour is fitness; hover a cell for its elite, click it to open it in the viewer (' + E.grown +
      ' fittest elites are in this report).';
    var canvas = $('heatmap'), ctx = canvas.getContext('2d');
    var W = canvas.width, H = canvas.height, L = 70, T = 14, Rm = 90, B = 46;
    var dx = D.length >= 2 ? 1 : -1, dy = 0;
    var lo = Infinity, hi = -Infinity;
    E.cells.forEach(function (c) { lo = Math.min(lo, c.fitness); hi = Math.max(hi, c.fitness); });
    function unit(c, d) { return (c.descriptors[d] - D[d].min) / (D[d].max - D[d].min); }
    var shapes = [];  // {x, y, w, h, cell}
    if (E.kind === 'grid') {
      var cols = dx >= 0 ? D[dx].bins : 1, rows = D[dy].bins;
      var cw = (W - L - Rm) / cols, ch = (H - T - B) / rows, shown = {};
      E.cells.forEach(function (c) {  // more than two descriptors: the fittest over the others
        var k = c.bins[dy] + ',' + (dx >= 0 ? c.bins[dx] : 0);
        if (!shown[k] || c.fitness > shown[k].fitness) shown[k] = c;
      });
      ctx.fillStyle = '#e6e9ec';
      ctx.fillRect(L, T, W - L - Rm, H - T - B);
      Object.keys(shown).forEach(function (k) {
        var c = shown[k], col = dx >= 0 ? c.bins[dx] : 0, row = c.bins[dy];
        shapes.push({ x: L + col * cw, y: T + (rows - 1 - row) * ch, w: cw, h: ch, cell: c });
      });
    } else {
      E.cells.forEach(function (c) {
        var x = L + (dx >= 0 ? unit(c, dx) : 0.5) * (W - L - Rm), y = T + (1 - unit(c, dy)) * (H - T - B);
        shapes.push({ x: x - 5, y: y - 5, w: 10, h: 10, cell: c });
      });
    }
    shapes.forEach(function (s) {
      ctx.fillStyle = heat(hi > lo ? (s.cell.fitness - lo) / (hi - lo) : 1);
      ctx.fillRect(s.x, s.y, s.w, s.h);
      if (s.cell.script) { ctx.strokeStyle = '#ffffff'; ctx.strokeRect(s.x + 1, s.y + 1, s.w - 2, s.h - 2); }
    });
    ctx.strokeStyle = '#8c959f';
    ctx.strokeRect(L, T, W - L - Rm, H - T - B);
    ctx.fillStyle = '#24292f';
    ctx.font = '12px system-ui, sans-serif';
    ctx.textAlign = 'right';
    ctx.fillText(fmt(D[dy].max), L - 4, T + 10);
    ctx.fillText(fmt(D[dy].min), L - 4, H - B);
    ctx.save(); ctx.translate(16, T + (H - T - B) / 2); ctx.rotate(-Math.PI / 2); ctx.textAlign = 'center';
    ctx.fillText(D[dy].name, 0, 0); ctx.restore();
    if (dx >= 0) {
      ctx.textAlign = 'left'; ctx.fillText(fmt(D[dx].min), L, H - B + 16);
      ctx.textAlign = 'right'; ctx.fillText(fmt(D[dx].max), W - Rm, H - B + 16);
      ctx.textAlign = 'center'; ctx.fillText(D[dx].name, L + (W - L - Rm) / 2, H - 10);
    }
    for (var i = 0; i <= 20; i++) {  // the colour scale
      ctx.fillStyle = heat(i / 20);
      ctx.fillRect(W - Rm + 20, T + (1 - (i + 1) / 21) * (H - T - B), 16, (H - T - B) / 21 + 1);
    }
    ctx.fillStyle = '#24292f';
    ctx.textAlign = 'left';
    ctx.fillText(fmt(hi), W - Rm + 40, T + 10);
    ctx.fillText(fmt(lo), W - Rm + 40, H - B);
    ctx.fillText('fitness', W - Rm + 16, H - B + 16);

    function at(ev) {
      var r = canvas.getBoundingClientRect();
      var x = (ev.clientX - r.left) * W / r.width, y = (ev.clientY - r.top) * H / r.height;
      for (var i = shapes.length - 1; i >= 0; i--) {
        var s = shapes[i];
        if (x >= s.x && x <= s.x + s.w && y >= s.y && y <= s.y + s.h) return s.cell;
      }
      return null;
    }
    canvas.addEventListener('mousemove', function (ev) {
      var c = at(ev);
      if (!c) { hideTip(); return; }
      showTip('cell ' + c.cell + ' · id ' + c.id + '\nfitness ' + fmt(c.fitness, 6) + '\n' +
        D.map(function (d, k) { return d.name + ' ' + fmt(c.descriptors[k], 5); }).join('\n') +
        (c.script ? '\nclick: open in the viewer' : '\nnot in this report (report --elites N)'), ev.clientX, ev.clientY);
    });
    canvas.addEventListener('mouseleave', hideTip);
    canvas.addEventListener('click', function (ev) {
      var c = at(ev);
      if (!c || !c.script) return;
      showInViewer(c.key, c.script, 'elite of cell ' + c.cell + ', fitness ' + fmt(c.fitness, 6));
      $('viewer-section').scrollIntoView({ behavior: 'smooth' });
    });
    status.heatmap = shapes.length;
    var target = shapes.find(function (s) { return s.cell.script; });  // for the browser tests: a cell to click
    if (target) status.heatmapTarget = { x: target.x + target.w / 2, y: target.y + target.h / 2, key: target.cell.key };
  }

  // ---------- contact sheet ----------
  function sheet() {
    if (!R.sheet) {
      $('sheet-intro').textContent = 'No exported generations to show.';
      $('sheet').hidden = true;
      return;
    }
    $('sheet-intro').textContent = 'The best of generations ' + R.sheet.generations.join(', ') + ', at one scale (software renderer).';
    $('sheet').src = R.sheet.image;
  }

  function guarded(name, f) {
    try { f(); } catch (e) { status.errors.push(name + ': ' + e.message); console.error(e); }
  }
  if (!R) {
    document.body.insertBefore(el('p', { 'class': 'message' }, 'data.js is missing: write the report again with morphogen report.'), document.body.firstChild);
    return;
  }
  guarded('summary', glance);
  guarded('plots', plots);
  guarded('ancestry', ancestry);
  guarded('archive', elites);
  guarded('contact sheet', sheet);
  guarded('viewer', viewers);
})();
