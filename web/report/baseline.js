// Against a baseline: each setting's time now over before (collido compare's rows), one chart
// per scene, and the settings whose count of wrong frames changed.
const ReportBaseline = (() => {
  'use strict';
  const { fmt, withInterval } = ReportFormat;
  const { el, section, table, empty } = ReportDom;
  const { chart } = ReportCharts;
  const { groupBy } = ReportModel;

  const labelOf = (r) => (r.setting ? r.backend + ' ' + r.setting : r.backend);
  // The compared rows with a ratio, as the charts' points.
  const ratiosOf = (changes) => changes.rows.filter((r) => typeof r.ratio === 'number')
    .map((r) => ({
      label: labelOf(r), scene: r.scene, query: r.query, ratio: r.ratio,
      lo: r.ratio_ci95[0], hi: r.ratio_ci95[1], change: r.change,
      interval: `[${fmt(r.ratio_ci95[0], 2)}, ${fmt(r.ratio_ci95[1], 2)}]`,
      before: withInterval(r.before_us, r.before_ci95_us),
      now: withInterval(r.now_us, r.now_ci95_us) }));
  // The measured rows whose count of wrong frames differs from the baseline's.
  function errorChanges(data, ok) {
    const before = new Map((data.baseline_rows || []).filter((r) => r.status === 'ok')
      .map((r) => [r.key, r]));
    const errors = [];
    for (const r of ok) {
      const b = before.get(r.key);
      if (b && b.disagreements !== r.disagreements) {
        errors.push([r.label, r.scene, r.query, String(b.disagreements), String(r.disagreements)]);
      }
    }
    return errors;
  }

  function ratioChart(box, scene, rows) {
    const x = { type: 'quantitative', scale: { type: 'log' }, title: 'now / before (mean time), 95% CI' };
    const colour = { field: 'change', type: 'nominal', title: 'change',
      scale: { domain: ['faster', 'same', 'slower'], range: ['#1b7f3b', '#9a9a9a', '#b3261e'] } };
    chart(box, 'comparison:' + scene, {
      title: scene, data: { values: rows }, width: 420, height: { step: 20 },
      encoding: { y: { field: 'label', type: 'nominal', title: null,
        axis: { labelLimit: 220, labelOverlap: false } } },
      layer: [
        { mark: { type: 'tick', color: '#888', thickness: 1 },
          encoding: { x: { datum: 1, type: 'quantitative' } } },
        { mark: { type: 'rule' },
          encoding: { x: Object.assign({ field: 'lo' }, x), x2: { field: 'hi' }, color: colour } },
        { mark: { type: 'point', filled: true, size: 70 },
          encoding: {
            x: Object.assign({ field: 'ratio' }, x),
            shape: { field: 'query', type: 'nominal' }, color: colour,
            tooltip: [{ field: 'label' }, { field: 'query' }, { field: 'before', title: 'before µs' },
              { field: 'now', title: 'now µs' }, { field: 'ratio', format: '.3f' },
              { field: 'interval', title: '95% interval' }, { field: 'change' }] } }] });
  }

  function render(model) {
    const { data, ok } = model;
    // The study decided each row (collido compare): now over before with its 95% interval, paired
    // by frame, and a change only where the whole interval lies beyond the equivalence band.
    const changes = data.baseline_changes || null;
    const bandText = changes ? fmt(100 * changes.equivalence_band, 0) + '%' : '10%';
    const s = section('comparison', 'Against a baseline',
      'Each setting against an earlier study of the same settings (collido report DIR --baseline ' +
      'OLD; collido compare OLD DIR prints the same rows): now / before of the mean over frames ' +
      'of each frame\'s median call, the whiskers its 95% interval, paired by frame. A row is ' +
      `faster (green) or slower (red) only when its whole interval lies beyond the ${bandText} ` +
      'equivalence band, a change both significant and large; the rest (grey) is the same ' +
      'within noise. Changes in error are listed.');
    if (!changes || !changes.rows || changes.rows.length === 0) {
      empty(s, !data.baseline_rows || data.baseline_rows.length === 0 ?
        'No baseline given: run collido report DIR --baseline EARLIER_DIR.' :
        'The baseline shares no measured setting with this study.');
      return;
    }
    const counts = changes.counts;
    s.appendChild(el('p', { class: 'baseline-counts', text: `${changes.rows.length} rows: ` +
      `${counts.faster} faster, ${counts.slower} slower, ${counts.same} the same.` }));
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    // One chart a scene, each listing only the settings that ran on it.
    for (const [scene, rows] of groupBy(ratiosOf(changes), (r) => r.scene)) {
      ratioChart(box, scene, rows);
    }
    const errors = errorChanges(data, ok);
    if (errors.length) {
      table(s, ['backend / setting', 'scene', 'query', 'wrong frames before', 'now'], errors,
        ['', '', '', 'num', 'num']);
    }
  }

  return { render };
})();
