// What the scene's needs save: each setting run with needs "every" against the same run with
// needs "declared" and "changed", in memory, build time and query time.
const ReportNeeds = (() => {
  'use strict';
  const { fmt, timeOf, ciOf, withInterval } = ReportFormat;
  const { el, section, laterTable, empty } = ReportDom;
  const { chart } = ReportCharts;

  const pct = (every, now) => (every > 0 ? ` (${Math.round(100 * (every - now) / every)}%)` : '');
  // As table.txt's needs table: the time with its 95% interval.
  const time = (r) => (r ? withInterval(timeOf(r), ciOf(r)) : '-');

  // The rows run with needs "every" beside the same setting, scene and query run "declared" and
  // "changed": one table line each, and a bar per needs for the charts.
  function comparisons(ok) {
    const key = (r) => r.backend + '|' + r.scene + '|' + r.resolution + '|' + r.limit + '|' + r.query;
    const byMode = (mode) => new Map(ok.filter((r) => r.needs === mode).map((r) => [key(r), r]));
    const declared = byMode('declared');
    const changed = byMode('changed');
    const bars = [];
    const rows = [];
    for (const e of ok.filter((r) => r.needs === 'every')) {
      const d = declared.get(key(e));
      const h = changed.get(key(e));
      const built = d || h;
      if (!built) continue;
      for (const [mode, r] of [['every', e], ['declared', d], ['changed', h]]) {
        if (!r) continue;
        bars.push({ backend: e.backend, scene: e.scene, query: e.query, needs: mode, build_ms: r.build_ms,
          bytes: r.bytes_per_triangle, time_us: timeOf(r), unasked_frames: r.unasked_frames || 0 });
      }
      rows.push([e.backend, e.scene, e.query,
        `${Math.round(e.bytes_per_triangle)} → ${Math.round(built.bytes_per_triangle)}` +
          pct(e.bytes_per_triangle, built.bytes_per_triangle),
        `${fmt(e.build_ms)} → ${fmt(built.build_ms)}` + pct(e.build_ms, built.build_ms),
        time(e), time(d), time(h),
        h ? `${h.unasked_frames || 0} of ${h.frames}` : '-',
        h ? `${h.reused_pairs || 0} / ${h.skipped_pairs || 0}` : '-',
        h ? String(h.disagreements) : '-']);
    }
    return { bars, rows };
  }

  function needsCharts(s, bars) {
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const charts = [['build_ms', 'build (ms)'], ['bytes', 'bytes per triangle'],
      ['time_us', 'mean query (µs)']];
    // Only "changed" answers frames without a query: without it the chart would be all zeros.
    if (bars.some((b) => b.unasked_frames > 0)) charts.push(['unasked_frames', 'frames answered without a query']);
    for (const [field, title] of charts) {
      const whole = field === 'unasked_frames' ? { format: 'd', tickMinStep: 1 } : {};
      chart(box, 'needs:' + field, {
        title: title, width: 300, height: { step: 10 }, data: { values: bars }, mark: 'bar',
        encoding: { y: { field: 'backend', type: 'nominal', title: null },
          yOffset: { field: 'needs' }, x: { field: field, type: 'quantitative', title: title,
            aggregate: 'median', axis: whole },
          color: { field: 'needs', type: 'nominal', sort: ['every', 'declared', 'changed'] },
          row: { field: 'scene', type: 'nominal', title: null } },
        // Scenes differ by orders of magnitude: each row gets its own scale.
        resolve: { scale: { x: 'independent' }, axis: { x: 'independent' } } });
    }
  }

  function render(model) {
    const s = section('needs', 'What the scene\'s needs save',
      'Scenes run three ways: every (each object built for every query kind the backend answers, ' +
      'every pair asked in every frame: the cold figure), declared (built for the scene\'s queries ' +
      'only) and changed (built as declared; a pair neither of whose objects moved, changed state or ' +
      'deformed since the frame before takes that answer instead of being asked, and a two-object ' +
      'collision query whose pair the shared broad phase proves apart is not asked; both answers ' +
      'are still checked against the exact reference). Query times are the mean over frames of ' +
      'each frame\'s median call, with its 95% interval in the table.');
    const { bars, rows } = comparisons(model.ok);
    if (rows.length === 0) {
      empty(s, 'The study ran no scene both with needs "every" and "declared" or "changed": ' +
        'add them to the sweep\'s "needs" (docs/STUDY.md).');
      return;
    }
    laterTable(s, ['backend / setting', 'scene', 'query', 'B/tri every → declared', 'build ms every → declared',
      'mean µs every', 'declared', 'changed', 'frames unasked', 'pairs reused / culled',
      'wrong (changed)'], rows);
    needsCharts(s, bars);
  }

  return { render };
})();
