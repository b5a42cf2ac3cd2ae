// The study data as the views read it: the measured rows, the backend families with their
// colours and marker shapes, the tags the chart filters read, and the failures by kind.
const ReportModel = (() => {
  'use strict';
  const { timeFields } = ReportFormat;

  const groupBy = (items, key) => {
    const map = new Map();
    for (const item of items) {
      const k = key(item);
      if (!map.has(k)) map.set(k, []);
      map.get(k).push(item);
    }
    return map;
  };

  // --- backend families -----------------------------------------------------------------------
  // A study may hold a hundred settings: charts colour by backend family (a handful), tell the
  // settings of one family apart by shape, and name them in tooltips and on the Pareto front.
  const family = (backend) => String(backend).split(/[:[]/)[0];
  const SHAPES = ['circle', 'square', 'triangle-up', 'diamond', 'cross', 'triangle-down',
    'triangle-left', 'triangle-right', 'wedge', 'arrow', 'stroke', 'triangle'];
  // The shape names themselves (no scale, no legend): the tooltip names the setting.
  const settingShape = { field: 'marker', type: 'nominal', scale: null, legend: null };
  function familiesOf(rows) {
    const families = [...new Set(rows.map((r) => family(r.backend)))].sort();
    const familyColour = { field: 'family', type: 'nominal', title: 'backend family',
      scale: { domain: families, scheme: 'tableau10' } };
    const markerOf = new Map();
    for (const f of families) {
      const labels = [...new Set(rows.filter((r) => family(r.backend) === f).map((r) => r.label))]
        .sort();
      labels.forEach((label, i) => markerOf.set(label, SHAPES[i % SHAPES.length]));
    }
    // The same colours everywhere; each legend lists only the families its chart shows.
    const familyColourOf = (values) => Object.assign({}, familyColour, { legend: {
      values: families.filter((f) => values.some((v) => v.family === f)) } });
    return { families, familyColour, familyColourOf, markerOf };
  }

  // --- tags the chart filters read ------------------------------------------------------------
  // What the filters read from a chart's datum: its family, the query kinds it covers
  // (",boolean,distance,") and whether it is exact on every frame.
  function taggers(rows, markerOf) {
    const rowOf = new Map(rows.map((r) => [r.label + '|' + r.scene + '|' + r.query, r]));
    const tagged = (item, fam, itemRows) => Object.assign({}, item, { family: fam,
      marker: markerOf.get(item.label) || 'circle',
      kinds: ',' + [...new Set(itemRows.map((r) => r.kind))].join(',') + ',',
      exact: itemRows.length > 0 &&
        itemRows.every((r) => r.status === 'ok' && r.disagreements === 0) });
    const tagRow = (r) => Object.assign(tagged(r, family(r.backend), [r]), timeFields(r));
    const tagByLookup = (item) => {
      const r = rowOf.get(item.label + '|' + item.scene + '|' + item.query);
      return tagged(item, family(r ? r.backend : item.label), r ? [r] : []);
    };
    return { tagged, tagRow, tagByLookup };
  }

  // --- failures -------------------------------------------------------------------------------
  // Three counts that mean different things: what went wrong in the run, what a backend answered
  // wrongly, and what a backend was never asked because it does not answer that query at all.
  function failuresOf(data) {
    const realFailures = data.failures.filter((f) => f.what !== 'unsupported' &&
      f.what !== 'wrong answers');
    const wrongAnswers = data.failures.filter((f) => f.what === 'wrong answers');
    const byDesign = data.failures.filter((f) => f.what === 'unsupported');
    // Once per backend setting, with its reasons ("ode does not answer all_pairs queries").
    const designGaps = [...groupBy(byDesign, (f) => f.label).values()].map((list) => ({
      label: list[0].label,
      reasons: [...new Set(list.map((f) => f.detail.replace(/^skipped: /, '')))],
      scenes: [...new Set(list.map((f) => f.scene))] }));
    // Settings the plan left out on a scene: they answer none of the kinds it asks.
    const notApplicable = data.not_applicable || [];
    return { realFailures, wrongAnswers, byDesign, designGaps, notApplicable };
  }

  // What every section is given (its `model`): the study `data`, the equivalence band `pickBand`,
  // the measured rows (`ok`, and `charted` of them), the families with their colours and markers,
  // the taggers (`tagged`, `tagRow`, `tagByLookup`) and the failures by kind.
  function build(data) {
    // Two times within this share of each other are practically the same (docs/STUDY.md).
    const pickBand = data.what_to_pick && typeof data.what_to_pick.equivalence_band === 'number' ?
      data.what_to_pick.equivalence_band : 0.1;
    const ok = data.rows.filter((r) => r.status === 'ok');
    // Settings run with needs "changed" time only the pairs they asked (a reused frame times at
    // 0): their times are not comparable with the others', so they are shown in the needs
    // section only.
    const charted = ok.filter((r) => r.needs !== 'changed');
    const families = familiesOf(data.rows);
    return Object.assign({ data, pickBand, ok, charted, settingShape },
      families, taggers(data.rows, families.markerOf), failuresOf(data));
  }

  return { groupBy, family, build };
})();
