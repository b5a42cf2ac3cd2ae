// Time distributions: every timed call of each setting, as a box plot per scene and query.
const ReportDistributions = (() => {
  'use strict';
  const { el, section, empty } = ReportDom;
  const { filteredChart } = ReportCharts;
  const { groupBy } = ReportModel;

  function render(model) {
    const { data, tagByLookup, familyColour } = model;
    const s = section('time-distributions', 'Time distributions',
      'Every timed call per backend setting (log scale): the box spans the middle half and the ' +
      'median, the whiskers the fastest and slowest call. Long tails are frames with dense contact.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    // One list of timed calls per measurement; a chart's point per call is made when it draws.
    const groups = groupBy(data.times, (t) => t.scene + ' · ' + t.query);
    if (groups.size === 0) empty(s, 'No timed call.');
    for (const [name, measurements] of groups) {
      const tagged = measurements.map(tagByLookup);
      // A frame answered without a query (needs "changed") made no call: its 0 is left out.
      const calls = () => tagged.flatMap((m) => m.us.filter((us) => us > 0).map((us) => ({
        label: m.label, family: m.family, kinds: m.kinds, exact: m.exact, us: us })));
      filteredChart(box, 'time-distribution:' + name, {
        title: name, width: 360, height: { step: 18 }, data: { values: calls },
        // In a layer: Vega-Lite refuses parameters on a boxplot's own spec.
        layer: [{ mark: { type: 'boxplot', extent: 'min-max', size: 12 },
          encoding: { y: { field: 'label', type: 'nominal', title: null, axis: { labelLimit: 220 } },
            x: { field: 'us', type: 'quantitative', scale: { type: 'log' },
              title: 'time per call (µs)' },
            color: Object.assign({}, familyColour, { legend: null }) } }] }, tagged);
    }
  }

  return { render };
})();
