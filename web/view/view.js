// The scene viewer (collido view): draws the scene frame by frame with three.js and colours the
// triangles a backend reports as intersecting, the oracle's, or the difference between them.
// Everything comes from the page itself (data, geometry and three.js inline), so it opens
// offline. window.collidoView is the interface the browser test drives.

const byId = (id) => document.getElementById(id);
const data = JSON.parse(byId('view-data').textContent);
const frames = data.scene.frames;

// three.js ships as ES modules importing one another by relative path; inline, each is loaded
// from a blob URL with its imports pointed at the blob it needs.
async function loadThree() {
  const url = (text) => URL.createObjectURL(new Blob([text], { type: 'text/javascript' }));
  const core = url(byId('three-core').textContent);
  const module = url(byId('three-module').textContent.split("'./three.core.js'")
    .join(JSON.stringify(core)));
  const controls = url(byId('orbit-controls').textContent.split("'three'")
    .join(JSON.stringify(module)));
  const THREE = await import(module);
  const { OrbitControls } = await import(controls);
  return { THREE, OrbitControls };
}

function decodeGeometry() {
  const text = byId('view-geometry').textContent.trim();
  const binary = atob(text);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes.buffer;
}

const floats = (buffer, [offset, count]) => new Float32Array(buffer, offset, count);
const uints = (buffer, [offset, count]) => new Uint32Array(buffer, offset, count);

// Colours of the highlight classes, and the neutral palette of the objects.
const CLASS_COLOURS = {
  matched: [243, 156, 18], missed: [224, 24, 60], extra: [31, 111, 255],
  reported: [243, 156, 18], oracle: [24, 165, 88], agreed: [24, 165, 88],
};
const CLASS_TEXT = {
  matched: 'reported and exact (matched pairs)', missed: 'missed: exact pairs not reported',
  extra: 'extra: reported pairs that do not intersect', reported: 'reported by the backend',
  oracle: 'intersecting (exact oracle)',
};
// Boolean and contact queries name a witness or a few pairs, not every pair, so their
// difference is of verdicts: a named pair that really intersects, one that does not, and the
// oracle's witness where the backend says apart.
const WITNESS_TEXT = {
  matched: 'named by the backend and intersecting', missed: 'missed: the oracle\'s witness (backend says apart)',
  extra: 'extra: named pairs that do not intersect', reported: 'named by the backend (witness or contacts)',
  oracle: 'intersecting (the exact oracle\'s witness or pairs)',
  agreed: 'the oracle\'s pairs, where the backend agrees but names none',
};
const PRIORITY = { missed: 3, extra: 2, matched: 1, reported: 1, oracle: 1, agreed: 0 };
const PALETTE = [[176, 186, 200], [205, 190, 170], [170, 200, 185], [200, 178, 200],
  [185, 196, 214], [214, 205, 170], [170, 190, 210], [210, 180, 170]];

const pairKey = (a, b) => `${a},${b}`;

// The answers of one backend's query in a frame, or null.
function frameAnswers(backend, queryName, frame) {
  if (!backend || !backend.answers) return null;
  const query = backend.answers.queries.find((q) => q.name === queryName);
  if (!query) return null;
  return { query, record: query.frames.find((f) => f.frame === frame) || null };
}

// Per object: triangle -> class, and the pair counts, for one query, backend, frame and mode.
function classify(backend, queryName, frame, mode) {
  const triangles = new Map();
  const counts = { matched: 0, missed: 0, extra: 0, reported: 0, oracle: 0, agreed: 0 };
  const found = frameAnswers(backend, queryName, frame);
  if (!found || !found.record) return { triangles, counts, status: found ? found.query.status : 'no answers' };
  const mark = (object, triangle, cls) => {
    if (!triangles.has(object)) triangles.set(object, new Map());
    const map = triangles.get(object);
    const old = map.get(triangle);
    if (!old || PRIORITY[cls] > PRIORITY[old]) map.set(triangle, cls);
  };
  const everyPair = found.query.kind === 'all_pairs';
  for (const pair of found.record.pairs) {
    const reported = new Set();
    for (let i = 0; i < pair.reported.length; i += 2) reported.add(pairKey(pair.reported[i], pair.reported[i + 1]));
    const exact = new Set();
    for (let i = 0; i < pair.oracle.length; i += 2) exact.add(pairKey(pair.oracle[i], pair.oracle[i + 1]));
    counts.reported += reported.size;
    counts.oracle += exact.size;
    const markPair = (key, cls) => {
      const [ta, tb] = key.split(',').map(Number);
      mark(pair.a, ta, cls);
      mark(pair.b, tb, cls);
    };
    if (mode === 'reported') for (const key of reported) markPair(key, 'reported');
    if (mode === 'oracle') for (const key of exact) markPair(key, 'oracle');
    if (mode === 'difference' && !everyPair) {
      const named = [...reported];
      named.forEach((key, k) => {
        const cls = pair.reported_exact && pair.reported_exact[k] ? 'matched' : 'extra';
        counts[cls] += 1;
        markPair(key, cls);
      });
      if (pair.oracle_intersecting && !pair.intersecting) {
        for (const key of exact) { counts.missed += 1; markPair(key, 'missed'); }
      } else if (pair.oracle_intersecting && named.length === 0) {
        for (const key of exact) { counts.agreed += 1; markPair(key, 'agreed'); }
      }
    }
    if (mode === 'difference' && everyPair) {
      for (const key of reported) {
        const cls = exact.has(key) ? 'matched' : 'extra';
        counts[cls] += 1;
        markPair(key, cls);
      }
      for (const key of exact) {
        if (!reported.has(key)) { counts.missed += 1; markPair(key, 'missed'); }
      }
    }
  }
  return { triangles, counts, status: found.query.status, record: found.record, query: found.query };
}

function composeMatrix(THREE, numbers) {
  return new THREE.Matrix4().fromArray(numbers);
}

async function main() {
  const { THREE, OrbitControls } = await loadThree();
  const buffer = decodeGeometry();
  const canvas = byId('canvas');
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  const scene = new THREE.Scene();
  const BACKGROUND = 0xeef1f5;
  scene.background = new THREE.Color(BACKGROUND);
  // The scene's up (+y unless it says otherwise; robots from URDF are +z up): sky, sun, camera
  // and orbit all turn with it.
  const up = new THREE.Vector3().fromArray(data.scene.up || [0, 1, 0]).normalize();
  const fromYUp = new THREE.Quaternion().setFromUnitVectors(new THREE.Vector3(0, 1, 0), up);
  const sky = new THREE.HemisphereLight(0xffffff, 0x8090a0, 2.2);
  sky.position.copy(up);
  scene.add(sky);
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(1, 2, 3).applyQuaternion(fromYUp);
  scene.add(sun);
  const camera = new THREE.PerspectiveCamera(45, 1, 0.01, 1000);
  camera.up.copy(up);
  const controls = new OrbitControls(camera, canvas);
  controls.addEventListener('change', () => render());

  // One mesh per object state (one draw call each); triangles unshared so each has its colour.
  const objects = data.objects.map((object, index) => {
    const base = PALETTE[index % PALETTE.length];
    const group = new THREE.Group();
    group.matrixAutoUpdate = false;
    scene.add(group);
    const states = object.states.map((state, s) => {
      const indices = uints(buffer, state.indices);
      const positions = new Float32Array(indices.length * 3);
      const colours = new Uint8Array(indices.length * 3);
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
      geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3, true));
      for (let k = 0; k < colours.length; k += 3) colours.set(base, k);
      const material = new THREE.MeshLambertMaterial({ vertexColors: true, side: THREE.DoubleSide });
      const mesh = new THREE.Mesh(geometry, material);
      mesh.userData = { object: index, state: s };
      group.add(mesh);
      return { mesh, indices, positions, colours, highlighted: [] };
    });
    const setVertices = (state, vertices) => {
      const { indices, positions, mesh } = state;
      for (let k = 0; k < indices.length; ++k) {
        const v = indices[k] * 3;
        positions[3 * k] = vertices[v];
        positions[3 * k + 1] = vertices[v + 1];
        positions[3 * k + 2] = vertices[v + 2];
      }
      mesh.geometry.attributes.position.needsUpdate = true;
      mesh.geometry.computeVertexNormals();
      mesh.geometry.computeBoundingSphere();
      mesh.geometry.computeBoundingBox();
    };
    object.states.forEach((state, s) => setVertices(states[s], floats(buffer, state.positions)));
    // The true pose of a tracked object (or of a child of one), as a faint ghost.
    let ghost = null;
    if (object.true_poses) {
      ghost = new THREE.Mesh(states[0].mesh.geometry, new THREE.MeshBasicMaterial(
        { color: 0x2b7a4b, wireframe: true, transparent: true, opacity: 0.12, depthWrite: false }));
      ghost.matrixAutoUpdate = false;
      scene.add(ghost);
    }
    let markers = null;
    if (object.markers) {
      const count = object.markers.layout.length;
      const makePoints = (colour) => {
        const geometry = new THREE.BufferGeometry();
        geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * count), 3));
        const points = new THREE.Points(geometry, new THREE.PointsMaterial(
          { color: colour, size: 8, sizeAttenuation: false }));
        scene.add(points);
        return points;
      };
      markers = { observed: makePoints(0xd35400), predicted: makePoints(0x1f6fff) };
    }
    return { data: object, base, group, states, setVertices, ghost, markers, activeState: -1 };
  });

  // Closest points of distance queries: the backend's and the oracle's.
  const segments = new THREE.Group();
  scene.add(segments);

  // The view starts framing the whole scene in frame 0.
  const box = new THREE.Box3();
  const fit = () => {
    scene.updateMatrixWorld();  // the groups' poses, before anything has been drawn
    box.makeEmpty();
    for (const o of objects) for (const s of o.states) if (s.mesh.visible) box.expandByObject(s.mesh);
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    const radius = Math.max(sphere.radius, 1e-6);
    controls.target.copy(sphere.center);
    camera.near = radius / 1000;
    camera.far = radius * 100;
    camera.position.copy(sphere.center).add(
      new THREE.Vector3(1.2, 0.9, 1.6).applyQuaternion(fromYUp).multiplyScalar(radius * 1.4));
    camera.updateProjectionMatrix();
    controls.update();
  };

  // Frames the camera on the highlighted triangles (all objects when none is).
  const focus = () => {
    box.makeEmpty();
    const corner = new THREE.Vector3();
    for (const o of objects) {
      const s = o.states[o.activeState];
      if (!s || s.highlighted.length === 0) continue;
      s.mesh.updateMatrixWorld(true);
      for (const t of s.highlighted) {
        for (let c = 0; c < 3; ++c) {
          corner.fromArray(s.positions, 9 * t + 3 * c).applyMatrix4(s.mesh.matrixWorld);
          box.expandByPoint(corner);
        }
      }
    }
    if (box.isEmpty()) { fit(); return false; }
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    const radius = Math.max(sphere.radius, 1e-3);
    const direction = camera.position.clone().sub(controls.target).normalize();
    controls.target.copy(sphere.center);
    camera.position.copy(sphere.center).addScaledVector(direction, radius * 5);
    camera.near = radius / 100;
    camera.updateProjectionMatrix();
    controls.update();
    return true;
  };

  const ui = {
    query: byId('query'), backend: byId('backend'), mode: byId('mode'), frame: byId('frame'),
    label: byId('frame-label'), play: byId('play'), prev: byId('prev'), next: byId('next'),
    focus: byId('focus'), whole: byId('whole'), xray: byId('xray'),
    legend: byId('legend'),
    verdicts: byId('verdicts'), picked: byId('picked'),
  };
  data.queries.forEach((q, i) => ui.query.add(new Option(`${q.name} (${q.kind})`, String(i))));
  data.backends.forEach((b, i) => ui.backend.add(new Option(b.label + (b.problem ? ' — no answers' : ''), String(i))));
  ui.frame.max = String(frames - 1);
  byId('description').textContent = data.scene.description;
  const tree = byId('objects');
  const depth = (i) => (data.objects[i].parent === null ? 0 : 1 + depth(data.objects[i].parent));
  data.objects.forEach((o, i) => {
    const item = document.createElement('li');
    item.style.paddingLeft = `${depth(i) * 14}px`;
    const colour = objects[i].base;
    item.innerHTML = `<span class="swatch" style="background: rgb(${colour.join(',')})"></span> `;
    item.append(`${o.name} — ${o.source}${o.markers ? ' (tracked markers)' : ''}`);
    tree.append(item);
  });

  const state = { frame: 0, query: 0, backend: 0, mode: 'difference', playing: false, highlighted: 0, counts: null, picked: null };

  function applyPoses(frame) {
    for (const o of objects) {
      const d = o.data;
      const pose = d.poses.length === 1 ? d.poses[0] : d.poses[frame];
      o.group.matrix.copy(composeMatrix(THREE, pose));
      o.group.matrixWorldNeedsUpdate = true;
      // An object added or removed mid-run (a recording) is drawn only while it exists.
      o.group.visible = !d.present || d.present.some(([from, to]) => frame >= from && frame <= to);
      const active = d.schedule ? d.schedule[frame] : 0;
      o.states.forEach((s, k) => { s.mesh.visible = k === active; });
      if (d.deformed) o.setVertices(o.states[active], floats(buffer, d.deformed[frame]));
      o.activeState = active;
      if (o.ghost) {
        o.ghost.geometry = o.states[active].mesh.geometry;
        o.ghost.matrix.copy(composeMatrix(THREE, d.true_poses[frame]));
        o.ghost.matrixWorldNeedsUpdate = true;
      }
      if (o.markers) {
        const m = d.markers;
        const observed = o.markers.observed.geometry.attributes.position;
        const seen = m.observed[frame] || [];
        observed.array.fill(0);
        seen.forEach(([, x, y, z], k) => observed.setXYZ(k, x, y, z));
        o.markers.observed.geometry.setDrawRange(0, seen.length);
        observed.needsUpdate = true;
        const predicted = o.markers.predicted.geometry.attributes.position;
        const matrix = composeMatrix(THREE, pose);
        m.layout.forEach(([, x, y, z], k) => {
          const p = new THREE.Vector3(x, y, z).applyMatrix4(matrix);
          predicted.setXYZ(k, p.x, p.y, p.z);
        });
        predicted.needsUpdate = true;
      }
    }
  }

  function applyHighlights() {
    const backend = data.backends[state.backend];
    const query = data.queries[state.query];
    const result = classify(backend, query.name, state.frame, state.mode);
    let highlighted = 0;
    const used = new Set();
    for (const o of objects) {
      for (const s of o.states) {
        for (const t of s.highlighted) {
          for (let corner = 0; corner < 3; ++corner) s.colours.set(o.base, 9 * t + 3 * corner);
        }
        if (s.highlighted.length) used.add(s);
        s.highlighted = [];
      }
    }
    for (const [objectIndex, map] of result.triangles) {
      const o = objects[objectIndex];
      const s = o.states[o.activeState];
      for (const [triangle, cls] of map) {
        if (9 * triangle + 8 >= s.colours.length) continue;
        const colour = CLASS_COLOURS[cls];
        s.colours.set(colour, 9 * triangle);
        s.colours.set(colour, 9 * triangle + 3);
        s.colours.set(colour, 9 * triangle + 6);
        s.highlighted.push(triangle);
        highlighted += 1;
      }
      used.add(s);
    }
    for (const s of used) s.mesh.geometry.attributes.color.needsUpdate = true;
    state.highlighted = highlighted;
    state.counts = result.counts;
    state.status = result.status;
    drawSegments(backend, query);
    drawLegend(result);
    drawVerdicts(query);
  }

  function drawSegments(backend, query) {
    for (const line of segments.children) { line.geometry.dispose(); line.material.dispose(); }
    segments.clear();
    if (query.kind !== 'distance') return;
    const found = frameAnswers(backend, query.name, state.frame);
    if (!found || !found.record) return;
    for (const pair of found.record.pairs) {
      for (const [key, colour] of [['distance', 0xf39c12], ['oracle_distance', 0x18a558]]) {
        const d = pair[key];
        if (!d) continue;
        const geometry = new THREE.BufferGeometry().setFromPoints(
          [new THREE.Vector3(...d.a), new THREE.Vector3(...d.b)]);
        segments.add(new THREE.Line(geometry, new THREE.LineBasicMaterial({ color: colour })));
      }
    }
  }

  function drawLegend(result) {
    const everyPair = data.queries[state.query].kind === 'all_pairs';
    const classes = state.mode !== 'difference' ? [state.mode]
      : everyPair || !result.counts.agreed ? ['matched', 'missed', 'extra'] : ['matched', 'missed', 'extra', 'agreed'];
    const text = everyPair ? CLASS_TEXT : WITNESS_TEXT;
    const rows = classes.map((cls) => {
      const count = result.counts[cls];
      return `<div><span class="swatch" style="background: rgb(${CLASS_COLOURS[cls].join(',')})"></span>` +
        `${text[cls]}: <b data-class="${cls}">${count}</b> pairs</div>`;
    });
    const backend = data.backends[state.backend];
    ui.legend.innerHTML = `<div><b>${escapeHtml(backend.label)}</b>&nbsp;· frame ${state.frame}</div>` +
      rows.join('') + `<div>highlighted triangles: <b id="highlighted-count">${state.highlighted}</b></div>` +
      (result.status && result.status !== 'ok' ? `<div class="bad">${escapeHtml(result.status)}</div>` : '') +
      (backend.problem ? `<div class="bad">${escapeHtml(backend.problem.slice(0, 200))}</div>` : '');
  }

  // Every backend's verdict on the chosen query in this frame, beside the oracle's.
  function drawVerdicts(query) {
    // A query asked in some frames only (a recording's) has no answers in the others.
    if (query.asked && !query.asked.some(([from, to]) => state.frame >= from && state.frame <= to)) {
      ui.verdicts.innerHTML = `<p>${escapeHtml(query.name)} is not asked in frame ${state.frame}.</p>`;
      return;
    }
    const rows = data.backends.map((backend) => {
      const found = frameAnswers(backend, query.name, state.frame);
      if (!found || !found.record) {
        const why = backend.problem || (found ? found.query.status : 'no answer');
        return `<tr><td>${escapeHtml(backend.label)}</td><td colspan="3" class="bad">${escapeHtml(why.slice(0, 120))}</td></tr>`;
      }
      const r = found.record;
      let verdict = '';
      // The runner's own judgement (tolerances, false witnesses, truncation) when given.
      let wrong = Boolean(r.disagrees);
      if (query.kind === 'all_pairs') {
        const missed = r.oracle_pairs - r.matched_pairs;
        const extra = r.reported_pairs - r.matched_pairs;
        if (r.disagrees === undefined) wrong = missed > 0 || extra > 0;
        verdict = `found ${r.matched_pairs} of ${r.oracle_pairs} exact pairs; ${missed} missed, ` +
          `${extra} extra (${r.reported_pairs} reported)`;
      } else if (query.kind === 'distance') {
        const d = r.pairs.map((p) => (p.distance ? p.distance.value : NaN));
        const exact = r.pairs.map((p) => (p.oracle_distance ? p.oracle_distance.value : NaN));
        verdict = `${d.map((x) => x.toPrecision(6)).join(', ')} (exact ${exact.map((x) => x.toPrecision(6)).join(', ')})`;
      } else {
        const said = r.pairs.some((p) => p.intersecting);
        const exact = r.pairs.some((p) => p.oracle_intersecting);
        if (r.disagrees === undefined) wrong = said !== exact;
        const falseWitnesses = r.pairs.reduce((n, p) => n + (p.reported_exact || []).filter((e) => !e).length, 0);
        verdict = `${said ? 'intersecting' : 'apart'} (exact: ${exact ? 'intersecting' : 'apart'})` +
          (falseWitnesses ? `; ${falseWitnesses} named pair(s) do not intersect` : '');
      }
      return `<tr><td>${escapeHtml(backend.label)}</td><td class="${wrong ? 'bad' : 'good'}">${escapeHtml(verdict)}</td>` +
        `<td class="num" title="object pairs asked">${r.object_pairs}</td>` +
        `<td class="num" title="frames that disagree with the oracle, whole run">${found.query.disagreements}</td></tr>`;
    });
    ui.verdicts.innerHTML = `<table><tr><th>backend</th><th>answer</th><th>obj. pairs</th><th>bad frames</th></tr>${rows.join('')}</table>`;
  }

  function escapeHtml(text) {
    return String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' }[c]));
  }

  // The pairs a picked triangle takes part in this frame, with every backend's verdict.
  function showPicked() {
    if (!state.picked) return;
    const { object, triangle } = state.picked;
    const query = data.queries[state.query];
    const everyPair = query.kind === 'all_pairs';
    const pairs = new Map();  // "other object:triangle" -> {oracle, backends: {label: bool}}
    for (const backend of data.backends) {
      const found = frameAnswers(backend, query.name, state.frame);
      if (!found || !found.record) continue;
      for (const pair of found.record.pairs) {
        if (pair.a !== object && pair.b !== object) continue;
        const mine = pair.a === object ? 0 : 1;
        const visit = (list, what) => {
          for (let i = 0; i < list.length; i += 2) {
            if (list[i + mine] !== triangle) continue;
            const other = mine === 0 ? [pair.b, list[i + 1]] : [pair.a, list[i]];
            const key = other.join(':');
            if (!pairs.has(key)) pairs.set(key, { other, oracle: false, backends: {} });
            if (what === 'oracle') pairs.get(key).oracle = true;
            else {
              pairs.get(key).backends[backend.label] = true;
              // A witness is checked exactly even where the oracle kept only its own witness.
              if (pair.reported_exact && pair.reported_exact[i / 2]) pairs.get(key).oracle = true;
            }
          }
        };
        visit(pair.oracle, 'oracle');
        visit(pair.reported, 'reported');
      }
    }
    const name = data.objects[object].name;
    let html = `<p><b>${escapeHtml(name)}</b> triangle <b id="picked-triangle">${triangle}</b> (object ${object}), frame ${state.frame}</p>`;
    if (pairs.size === 0) {
      html += '<p class="hint">No backend and not the oracle pair it with a triangle in this query and frame.</p>';
    } else {
      const labels = data.backends.filter((b) => b.answers).map((b) => b.label);
      html += `<table><tr><th>with</th><th>exact</th>${labels.map((l) => `<th>${escapeHtml(l)}</th>`).join('')}</tr>`;
      for (const entry of pairs.values()) {
        const cells = labels.map((l) => {
          const said = Boolean(entry.backends[l]);
          // Boolean and contact answers name some pairs, not all: leaving one out is no error.
          if (!everyPair && !said) return '<td>&ndash;</td>';
          return `<td class="${said === entry.oracle ? 'good' : 'bad'}">${said ? '&#10003;' : '&#10007;'}</td>`;
        });
        html += `<tr><td>${escapeHtml(data.objects[entry.other[0]].name)} #${entry.other[1]}</td>` +
          `<td>${entry.oracle ? '&#10003;' : '&#10007;'}</td>${cells.join('')}</tr>`;
      }
      html += '</table>';
    }
    ui.picked.innerHTML = html;
  }

  function resize() {
    const width = canvas.parentElement.clientWidth;
    const height = canvas.parentElement.clientHeight;
    renderer.setSize(width, height, false);
    camera.aspect = width / Math.max(height, 1);
    camera.updateProjectionMatrix();
  }

  function render() { renderer.render(scene, camera); }

  function setFrame(frame) {
    state.frame = Math.max(0, Math.min(frames - 1, frame));
    ui.frame.value = String(state.frame);
    ui.label.textContent = `frame ${state.frame} / ${frames - 1}`;
    applyPoses(state.frame);
    applyHighlights();
    showPicked();
    render();
  }
  const refresh = () => { applyHighlights(); showPicked(); render(); };

  ui.frame.addEventListener('input', () => setFrame(Number(ui.frame.value)));
  ui.prev.addEventListener('click', () => setFrame(state.frame - 1));
  ui.next.addEventListener('click', () => setFrame(state.frame + 1));
  ui.query.addEventListener('change', () => { state.query = Number(ui.query.value); refresh(); });
  ui.backend.addEventListener('change', () => { state.backend = Number(ui.backend.value); refresh(); });
  ui.mode.addEventListener('change', () => { state.mode = ui.mode.value; refresh(); });
  let timer = null;
  const setPlaying = (playing) => {
    state.playing = playing;
    ui.play.innerHTML = playing ? '&#10074;&#10074;' : '&#9654;';
    if (timer) clearInterval(timer);
    timer = playing ? setInterval(() => setFrame((state.frame + 1) % frames), 125) : null;
  };
  ui.play.addEventListener('click', () => setPlaying(!state.playing));
  ui.focus.addEventListener('click', () => { focus(); render(); });
  ui.whole.addEventListener('click', () => { fit(); render(); });
  window.addEventListener('keydown', (event) => {
    // Lists and the slider step by the arrow keys themselves.
    if (event.target instanceof HTMLSelectElement || event.target instanceof HTMLInputElement) return;
    if (event.key === ' ' && !(event.target instanceof HTMLButtonElement)) {
      setPlaying(!state.playing);
      event.preventDefault();
    }
    if (event.key === 'ArrowLeft') setFrame(state.frame - 1);
    if (event.key === 'ArrowRight') setFrame(state.frame + 1);
  });
  window.addEventListener('resize', () => { resize(); render(); });

  // Picking: a click (not a drag of the camera) selects the triangle under the pointer.
  const raycaster = new THREE.Raycaster();
  let down = null;
  canvas.addEventListener('pointerdown', (event) => { down = [event.clientX, event.clientY]; });
  canvas.addEventListener('pointerup', (event) => {
    if (!down || Math.hypot(event.clientX - down[0], event.clientY - down[1]) > 4) return;
    const rect = canvas.getBoundingClientRect();
    const pointer = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1,
      -((event.clientY - rect.top) / rect.height) * 2 + 1);
    pick(pointer);
  });
  function pick(pointer) {
    raycaster.setFromCamera(pointer, camera);
    const meshes = objects.flatMap((o) => o.states.map((s) => s.mesh)).filter((m) => m.visible);
    const hit = raycaster.intersectObjects(meshes, false)[0];
    state.picked = hit ? { object: hit.object.userData.object, triangle: hit.faceIndex } : null;
    if (!hit) ui.picked.innerHTML = '<p class="hint">Nothing under the pointer.</p>';
    showPicked();
    return state.picked;
  }

  // Pixels of the picture as drawn now: how many differ from the background, and a digest.
  function pixels() {
    render();
    const gl = renderer.getContext();
    const width = gl.drawingBufferWidth;
    const height = gl.drawingBufferHeight;
    const rgba = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
    const bg = [(BACKGROUND >> 16) & 255, (BACKGROUND >> 8) & 255, BACKGROUND & 255];
    let drawn = 0;
    let hash = 2166136261;
    for (let i = 0; i < rgba.length; i += 4) {
      if (Math.abs(rgba[i] - bg[0]) > 3 || Math.abs(rgba[i + 1] - bg[1]) > 3 || Math.abs(rgba[i + 2] - bg[2]) > 3) drawn += 1;
      hash = Math.imul(hash ^ rgba[i] ^ (rgba[i + 1] << 8) ^ (rgba[i + 2] << 16), 16777619) >>> 0;
    }
    return { width, height, drawn, hash };
  }

  window.collidoView = {
    setFrame: (f) => setFrame(f),
    setQuery: (name) => {
      const index = data.queries.findIndex((q) => q.name === name);
      if (index < 0) throw new Error(`no query named ${name}`);
      state.query = index;
      ui.query.value = String(index);
      refresh();
    },
    setBackend: (label) => {
      const index = data.backends.findIndex((b) => b.label === label);
      if (index < 0) throw new Error(`no backend ${label}`);
      state.backend = index;
      ui.backend.value = String(index);
      refresh();
    },
    setMode: (mode) => { state.mode = mode; ui.mode.value = mode; refresh(); },
    state: () => ({ frame: state.frame, highlighted: state.highlighted, counts: state.counts, status: state.status, picked: state.picked }),
    pixels,
    pick: (x, y) => pick(new THREE.Vector2(x, y)),
    focus: () => { const found = focus(); render(); return found; },
    view: (direction) => {
      const radius = camera.position.distanceTo(controls.target);
      camera.position.copy(controls.target).addScaledVector(new THREE.Vector3(...direction).normalize(), radius);
      controls.update();
      render();
    },
    // Triangles drawn in a highlight colour, counted from the colour buffers themselves.
    drawnHighlights: () => {
      const colours = Object.values(CLASS_COLOURS).map((c) => c.join(','));
      let count = 0;
      for (const o of objects) {
        const s = o.states[o.activeState];
        for (let t = 0; 9 * t < s.colours.length; ++t) {
          if (colours.includes(Array.from(s.colours.subarray(9 * t, 9 * t + 3)).join(','))) count += 1;
        }
      }
      return count;
    },
    backends: () => data.backends.map((b) => b.label),
    queries: () => data.queries.map((q) => q.name),
  };

  // X-ray: every mesh see-through, so triangles inside another mesh show their colours.
  ui.xray.addEventListener('change', () => {
    for (const o of objects) {
      for (const s of o.states) {
        s.mesh.material.transparent = ui.xray.checked;
        s.mesh.material.opacity = ui.xray.checked ? 0.3 : 1;
        s.mesh.material.depthWrite = !ui.xray.checked;
        s.mesh.material.needsUpdate = true;
      }
    }
    render();
  });

  resize();
  applyPoses(0);
  fit();
  // Open where something happens: the first frame whose exact answer to the first query has
  // contact (any backend's answers carry the oracle's).
  const firstContact = () => {
    const query = data.queries[0];
    for (let frame = 0; query && frame < frames; ++frame) {
      for (const backend of data.backends) {
        const found = frameAnswers(backend, query.name, frame);
        const r = found && found.record;
        if (r && (r.oracle_pairs > 0 || (r.pairs || []).some((p) => p.oracle_intersecting))) return frame;
      }
    }
    return 0;
  };
  setFrame(firstContact());
  document.body.setAttribute('data-ready', 'true');
}

main().catch((error) => {
  console.error(`view: ${error && error.stack ? error.stack : error}`);
  document.body.setAttribute('data-ready', 'failed');
});
