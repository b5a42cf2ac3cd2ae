// Memory per triangle: the backend's own figure and the heap its build kept (allocation hooks),
// one bar chart per scene.
const ReportMemory = (() => {
  'use strict';
  const { el, section, empty } = ReportDom;
  const { filteredChart } = ReportCharts;
  const { groupBy, family } = ReportModel;

  // Two bars per setting and scene: the backend's figure and, where counted, the heap kept.
  function memoryBars(model) {
    const { charted, tagged } = model;
    const rows = [];
    for (const [, queries] of groupBy(charted, (r) => r.label + '|' + r.scene)) {
      const r = queries[0];
      const bar = (measure, bytes) => tagged({ label: r.label, scene: r.scene, measure: measure,
        bytes: bytes, rss_mib: r.backend_rss_mib, heap_peak: r.heap_peak_bytes_per_triangle },
      family(r.backend), queries);
      rows.push(bar('backend figure', r.bytes_per_triangle));
      if (typeof r.heap_bytes_per_triangle === 'number') rows.push(bar('heap kept (hooks)', r.heap_bytes_per_triangle));
    }
    return rows;
  }

  function render(model) {
    const s = section('memory', 'Memory per triangle',
      'Bytes per triangle of the built structures of both objects: what the backend says, and ' +
      'what its build kept on the heap, counted by allocation hooks in the worker ' +
      '(independent of the backend). The tooltip adds the build peak and the resident memory ' +
      'the backend added at its peak, apart from the scene and the exact answers the worker held.');
    const rows = memoryBars(model);
    if (rows.length === 0) {
      empty(s, 'No built structure.');
      return;
    }
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    // One chart per scene, listing only the settings run on it.
    for (const [scene, bars] of groupBy(rows, (r) => r.scene)) {
      filteredChart(box, 'memory:' + scene, {
        title: scene, data: { values: bars }, width: 300, height: { step: 10 }, mark: 'bar',
        encoding: { y: { field: 'label', type: 'nominal', title: null, axis: { labelLimit: 220 } },
          yOffset: { field: 'measure' },
          x: { field: 'bytes', type: 'quantitative', title: 'bytes per triangle' },
          color: model.familyColourOf(bars),
          opacity: { field: 'measure', type: 'ordinal', title: null, scale: { range: [1, 0.45] } },
          tooltip: [{ field: 'label' }, { field: 'measure' }, { field: 'bytes', format: '.0f' },
            { field: 'heap_peak', title: 'build peak B/tri', format: '.0f' },
            { field: 'rss_mib', title: 'backend peak RSS (MiB)', format: '.0f' }] } }, bars);
    }
  }

  return { render };
})();
