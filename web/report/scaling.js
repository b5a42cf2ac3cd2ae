// Scaling: time and memory per triangle against the triangle count for scenes run at several
// resolutions, with the fitted exponent k of time ~ n^k.
const ReportScaling = (() => {
  'use strict';
  const { fmt, timeOf, TIME_TITLE } = ReportFormat;
  const { el, section, table, empty } = ReportDom;
  const { filteredChart } = ReportCharts;
  const { groupBy } = ReportModel;

  // Least-squares slope of log(y) on log(x): the exponent of y ~ x^k.
  function fittedExponent(points, x, y) {
    const usable = points.filter((p) => p[x] > 0 && p[y] > 0);
    if (usable.length < 2) return null;
    const lx = usable.map((p) => Math.log(p[x]));
    const ly = usable.map((p) => Math.log(p[y]));
    const mx = lx.reduce((a, b) => a + b, 0) / lx.length;
    const my = ly.reduce((a, b) => a + b, 0) / ly.length;
    let sxy = 0;
    let sxx = 0;
    for (let i = 0; i < lx.length; ++i) { sxy += (lx[i] - mx) * (ly[i] - my); sxx += (lx[i] - mx) ** 2; }
    return sxx > 0 ? sxy / sxx : null;
  }

  // The time and memory charts of one scene and query.
  function curveCharts(box, name, rows, familyColourOf) {
    const y = { field: 'time_us', type: 'quantitative', scale: { type: 'log' }, title: TIME_TITLE };
    filteredChart(box, 'scaling:' + name, {
      title: name, width: 360, height: 240, data: { values: rows },
      encoding: { x: { field: 'triangles', type: 'quantitative', scale: { type: 'log' },
        title: 'triangles (both objects)' },
      y: y,
      color: familyColourOf(rows) },
      layer: [
        // The whiskers share the time axis: the same scale and title, or Vega-Lite would
        // join two.
        { mark: { type: 'rule', opacity: 0.7, strokeWidth: 1.5 },
          encoding: { y: Object.assign({}, y, { field: 'ci_lo_us' }), y2: { field: 'ci_hi_us' },
            detail: { field: 'series' } } },
        { mark: { type: 'line', point: true },
          encoding: { detail: { field: 'series' },
            tooltip: [{ field: 'label' }, { field: 'triangles' },
              { field: 'time_us', title: 'mean µs', format: '.1f' },
              { field: 'time_ci95', title: '95% CI (µs)' }] } }] },
    rows);
    filteredChart(box, 'scaling-memory:' + name, {
      title: name + ' · memory', width: 360, height: 240, data: { values: rows },
      encoding: { x: { field: 'triangles', type: 'quantitative', scale: { type: 'log' },
        title: 'triangles (both objects)' },
      y: { field: 'bytes_per_triangle', type: 'quantitative', scale: { type: 'log' },
        title: 'bytes per triangle (backend figure)' },
      color: familyColourOf(rows) },
      layer: [{ mark: { type: 'line', point: true },
        encoding: { detail: { field: 'series' },
          tooltip: [{ field: 'label' }, { field: 'triangles' },
            { field: 'bytes_per_triangle', format: '.0f' },
            { field: 'backend_rss_mib', title: 'backend peak RSS (MiB)', format: '.1f' }] } }] },
    rows);
  }

  function render(model) {
    const { charted, tagRow, familyColourOf } = model;
    const s = section('scaling', 'Scaling',
      'Time per query (the mean over frames of each frame\'s median call, whiskers its 95% ' +
      'interval) and memory against the number of triangles (log-log), for scenes ' +
      'run at several resolutions. The table gives the fitted exponent k of time ~ n^k.');
    const curves = [];
    const exponents = [];
    for (const [name, rows] of groupBy(charted, (r) => r.scene + ' · ' + r.query)) {
      if (new Set(rows.map((r) => r.triangles)).size < 2) continue;
      // One curve per setting: the label without the resolution, which is the x axis here.
      const series = (r) => r.backend + (r.needs !== 'declared' ? ' needs=' + r.needs : '') +
          (r.limit ? ' limit=' + r.limit : '');
      for (const r of rows) curves.push(Object.assign(tagRow(r), { group: name, series: series(r) }));
      for (const [backend, points] of groupBy(rows, series)) {
        exponents.push([name, backend, String(new Set(points.map((p) => p.triangles)).size),
          fmt(fittedExponent(points.map((p) => ({ triangles: p.triangles, time_us: timeOf(p) })),
            'triangles', 'time_us'), 2),
          fmt(fittedExponent(points, 'triangles', 'bytes_per_triangle'), 2)]);
      }
    }
    if (curves.length === 0) {
      empty(s, 'No scene was run at more than one size: add "resolutions" to the sweep ' +
        '(e.g. scenes/sweeps/full.json) to see scaling.');
      return;
    }
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    for (const [name, rows] of groupBy(curves, (r) => r.group)) {
      curveCharts(box, name, rows, familyColourOf);
    }
    table(s, ['scene · query', 'backend', 'sizes', 'time exponent', 'B/tri exponent'], exponents,
      ['', '', 'num', 'num', 'num']);
  }

  return { render };
})();
