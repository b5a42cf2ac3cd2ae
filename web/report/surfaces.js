// Exact geometry against meshes: NURBS surface distances (collido surface-distance files) and
// FRep solids' guaranteed collision test against polygonizations (collido frep files).
const ReportSurfaces = (() => {
  'use strict';
  const { fmt } = ReportFormat;
  const { el, section, table, empty } = ReportDom;
  const { chart } = ReportCharts;

  // The backends that failed and the comparison's problems, as a list under its chart.
  function problemList(s, c, failed, name) {
    const problems = (c.problems || []).map((p) => el('li', { text: p }));
    if (failed.length + problems.length > 0) {
      s.appendChild(el('ul', {}, problems.concat(failed.map((b) => el('li', { text: name(b) +
        ': ' + b.status })))));
    }
  }

  // --- NURBS surfaces -------------------------------------------------------------------------
  // One surface pair: each backend's time against its error, and the seed method's work.
  function surfaceComparison(s, c, surfaceBackends) {
    const name = (c.name || c.file) + ': ' + c.a + ' · ' + c.b;
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const answered = c.backends.filter((b) => b.status === 'ok');
    const values = answered.map((b) => Object.assign({}, b, {
      label: b.segments > 0 ? b.backend + ' @' + b.segments : b.backend,
      shape: b.segments > 0 ? 'tessellation' : 'surfaces',
      relative_error: Math.max(Math.abs(b.error) / c.model_size, 1e-16) }));
    if (values.length > 0) {
      chart(box, 'surfaces:' + name, {
        title: name, width: 420, height: 240, data: { values: values },
        mark: { type: 'point', filled: true, size: 80 },
        encoding: {
          x: { field: 'median_us', type: 'quantitative', scale: { type: 'log' },
            title: 'median time per query (µs)', axis: { format: '~s', labelOverlap: 'greedy' } },
          y: { field: 'relative_error', type: 'quantitative', scale: { type: 'log' },
            title: '|error| / model size' },
          color: { field: 'backend', type: 'nominal', title: 'backend',
            scale: { domain: surfaceBackends } },
          shape: { field: 'shape', type: 'nominal', title: 'answers on' },
          tooltip: [{ field: 'label', title: 'backend' }, { field: 'distance', format: '.12g' },
            { field: 'error', format: '.3g' }, { field: 'median_us', format: '.1f' },
            { field: 'triangles' }, { field: 'build_ms', title: 'build ms', format: '.2f' }] } });
    } else {
      empty(box, name + ': no backend answered.');
    }
    const seeds = (c.seed || []).map((r) => [r.bound + (r.descent ? ' + descent' : ' (seed)'),
      r.lower.toPrecision(12), r.upper.toPrecision(12), (r.upper - r.lower).toPrecision(2),
      r.converged ? 'yes' : 'no', String(r.pairs_bounded), String(r.levels.length),
      fmt(r.median_ms, 3)]);
    if (seeds.length > 0) {
      table(s, ['bound', 'lower', 'upper', 'gap', 'converged', 'pairs bounded', 'levels',
        'median ms'], seeds);
    }
    problemList(s, c, c.backends.filter((b) => b.status !== 'ok'),
      (b) => b.backend + (b.segments > 0 ? ' @' + b.segments : ''));
  }

  function surfaces(model) {
    const s = section('surfaces', 'NURBS surfaces: run time against error',
      'From the study\'s surface files (collido study --surfaces FILE, each backend in a ' +
      'worker of its own; or collido report --surface-distance F with a collido ' +
      'surface-distance --json file; tools/study.sh runs every scenes/surfaces file): per surface pair, each backend\'s median ' +
      'time per distance query against its error, measured from the middle of the seed ' +
      'method\'s certified interval (1e-10 of the model\'s size wide), relative to the model\'s ' +
      'size (log scales; an error below 1e-16 is drawn at 1e-16). Surface backends (the seed as ' +
      'nurbs:*, OpenCASCADE as occt:*) answer on the surfaces; mesh backends on tessellations ' +
      '(the label gives the segments per parameter; the tooltip the build time). Below each ' +
      'chart, the seed method\'s work with hull and with box bounds, and the failures.');
    const comparisons = model.data.surfaces || [];
    if (comparisons.length === 0) empty(s, 'No surface comparison in this study (collido ' +
      'study ... --surfaces FILE, or collido report DIR --surface-distance F).');
    // One colour per backend across every chart.
    const surfaceBackends = [...new Set(comparisons.flatMap((c) => c.backends.map((b) => b.backend)))]
      .sort();
    for (const c of comparisons) surfaceComparison(s, c, surfaceBackends);
  }

  // --- FRep solids ----------------------------------------------------------------------------
  // One FRep file: the octree's time and the mesh routes' against their wrong answers, the
  // preview, and the octree's verdicts.
  function frepComparison(s, c, frepBackends) {
    const name = c.name || c.file;
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const seedMs = (c.seed || []).map((r) => r.median_ms).sort((a, b) => a - b);
    const median = seedMs.length ? seedMs[Math.floor((seedMs.length - 1) / 2)] : null;
    const values = c.comparators.filter((b) => b.status === 'ok').map((b) => {
      const decided = b.agrees + b.missed + b.false_contacts;
      return { backend: b.backend, label: b.backend + ' @' + b.resolution,
        resolution: b.resolution, ms: Math.max(b.ms_per_query_with_meshing, 1e-4),
        wrong_rate: decided > 0 ? b.wrong / decided : 0, missed: b.missed,
        false_contacts: b.false_contacts, triangles: b.triangles_first_pair };
    });
    if (median !== null) {
      values.push({ backend: 'frep:octree', label: 'frep:octree (ε ' + c.precision + ')',
        resolution: null, ms: Math.max(median, 1e-4), wrong_rate: 0, missed: 0,
        false_contacts: 0, triangles: null });
    }
    chart(box, 'frep:' + name, {
      title: name, width: 420, height: 240, data: { values: values },
      mark: { type: 'point', filled: true, size: 80 },
      encoding: {
        x: { field: 'ms', type: 'quantitative', scale: { type: 'log' },
          title: 'time per query, ms (mesh route: with polygonization)' },
        y: { field: 'wrong_rate', type: 'quantitative', title: 'share of wrong answers',
          scale: { domain: [0, 1] } },
        color: { field: 'backend', type: 'nominal', title: 'backend',
          scale: { domain: frepBackends } },
        tooltip: [{ field: 'label', title: 'backend' }, { field: 'ms', format: '.3f' },
          { field: 'wrong_rate', format: '.2f' }, { field: 'missed' },
          { field: 'false_contacts', title: 'false contacts' }, { field: 'triangles' }] } });
    if (c.preview_png) {
      box.appendChild(el('img', { class: 'preview', src: c.preview_png,
        alt: 'ray-cast preview of ' + name, 'data-view': 'frep-preview:' + name }));
    }
    const verdicts = {};
    for (const r of c.seed || []) verdicts[r.verdict] = (verdicts[r.verdict] || 0) + 1;
    const cells = Math.max(0, ...(c.seed || []).map((r) => r.cells));
    table(s, ['pair queries', 'verdicts', 'octree median ms', 'max ms', 'max cells', 'precision'],
      [[String((c.seed || []).length),
        Object.entries(verdicts).map(([k, v]) => v + ' ' + k).join(', '),
        fmt(median, 3), fmt(seedMs.length ? seedMs[seedMs.length - 1] : null, 3), String(cells),
        String(c.precision)]]);
    problemList(s, c, c.comparators.filter((b) => b.status !== 'ok'),
      (b) => b.backend + ' @' + b.resolution);
  }

  function frep(model) {
    const s = section('frep', 'FRep solids: run time against error',
      'From the study\'s FRep files (collido study --frep FILE, each backend in a worker of ' +
      'its own; or collido report --frep F with a collido frep --json file; tools/study.sh runs every ' +
      'scenes/frep file): per FRep file, the seed method\'s guaranteed octree test (frep:octree, ' +
      'never wrong: its answers are the reference) against mesh backends on OpenVDB ' +
      'polygonizations at several grid resolutions. Each point is the time per query (log scale; ' +
      'for the mesh route it includes polygonizing and building every mesh that changed in that ' +
      'frame) against the share of wrong answers (missed overlaps and false contacts; frames the ' +
      'octree calls touching within its precision are not counted). Beside each chart, the ' +
      'preview (the witness of the first collision as a red dot) and the octree\'s verdicts.');
    const comparisons = model.data.frep || [];
    if (comparisons.length === 0) empty(s, 'No FRep comparison in this study (collido study ' +
      '... --frep FILE, or collido report DIR --frep F).');
    const frepBackends = ['frep:octree', ...new Set(comparisons.flatMap(
      (c) => c.comparators.map((b) => b.backend)))].sort();
    for (const c of comparisons) frepComparison(s, c, frepBackends);
  }

  return { surfaces, frep };
})();
