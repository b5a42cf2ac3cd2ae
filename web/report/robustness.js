// The robustness matrix: every setting on the stress scenes by robustness category, the share of
// cases answered wrongly per question (boolean, all pairs, distance), and every count in a table.
const ReportRobustness = (() => {
  'use strict';
  const { fmt } = ReportFormat;
  const { el, section, laterTable, empty } = ReportDom;
  const { chart } = ReportCharts;

  const pct = (x) => (x === null || x === undefined) ? '-' : fmt(100 * x, 1) + '%';

  // A cell's figures for one question of the matrix.
  const cellValues = (cells, kind) => cells.map((c) => {
    const a = kind === 'boolean' ? c.boolean : kind === 'distance' ? c.distance : c.all_pairs;
    const measured = a.status === 'measured';
    return {
      backend: c.backend, category: c.category, cases: c.cases, status: a.status,
      rate: measured ? a.wrong_rate : null,
      // 'none': the category asks no such question (distance cases ask no boolean, and the
      // reverse), neither answered nor failed.
      text: measured ? (a.wrong === 0 ? '0' : pct(a.wrong_rate)) :
        a.status === 'none' ? 'not asked' : a.status,
      wrong: a.wrong, answered: a.answered, false_negatives: a.false_negatives,
      false_positives: a.false_positives, unsupported: a.unsupported, failed: a.failed,
      invalid_pairs: a.invalid_pairs,
      true_pairs: a.true_pairs === undefined ? null : a.true_pairs,
      missed: a.missed_pairs === undefined ? null : a.missed_pairs + ' (' + pct(a.missed_share) + ')',
      extra: a.extra_pairs === undefined ? null : a.extra_pairs + ' (' + pct(a.extra_share) + ')',
      workers: c.worker_failures.join('; ') || null };
  });

  function matrixTooltip(kind) {
    const tooltip = [{ field: 'backend' }, { field: 'category' }, { field: 'cases' },
      { field: 'status' }, { field: 'answered' }, { field: 'wrong' },
      { field: 'rate', title: 'wrong rate', format: '.4f' },
      { field: 'false_negatives', title: 'false negatives' },
      { field: 'false_positives', title: 'false positives' }];
    if (kind === 'all_pairs') {
      tooltip.push({ field: 'true_pairs', title: 'true pairs' },
        { field: 'missed', title: 'missed pairs (share of true)' },
        { field: 'extra', title: 'extra pairs (share of reported)' });
    }
    tooltip.push({ field: 'invalid_pairs', title: 'invalid pairs / false witnesses' },
      { field: 'unsupported', title: 'unsupported queries' },
      { field: 'failed', title: 'queries without an answer' },
      { field: 'workers', title: 'workers that died' });
    return tooltip;
  }

  // One question's matrix: settings down, categories across.
  function matrixChart(box, cells, kind, title) {
    const categories = [...new Set(cells.map((c) => c.category))];
    const settings = [...new Set(cells.map((c) => c.backend))];
    const x = { field: 'category', type: 'nominal', sort: categories, title: null,
      axis: { labelAngle: -30 } };
    const y = { field: 'backend', type: 'nominal', sort: settings, title: null,
      axis: { labelLimit: 420 } };
    chart(box, 'robustness:' + kind, {
      title: title, data: { values: cellValues(cells, kind) },
      width: { step: 78 }, height: { step: 20 },
      encoding: { x: x, y: y, tooltip: matrixTooltip(kind) },
      layer: [
        { transform: [{ filter: 'datum.rate !== null' }], mark: { type: 'rect', stroke: '#fff' },
          encoding: { color: {
            condition: { test: 'datum.rate === 0', value: '#cfead4' },
            field: 'rate', type: 'quantitative', title: 'share wrong',
            scale: { type: 'sqrt', domain: [0, 1], scheme: 'orangered' } } } },
        { transform: [{ filter: 'datum.rate === null' }], mark: { type: 'rect', stroke: '#fff' },
          encoding: { color: {
            condition: [{ test: "datum.status === 'unsupported'", value: '#d4d4d4' },
              { test: "datum.status === 'none'", value: '#f4f4f4' }],
            value: '#a5806a' } } },
        { mark: { type: 'text', fontSize: 9 },
          encoding: { text: { field: 'text' },
            color: { condition: { test: 'datum.rate > 0.3', value: '#fff' }, value: '#222' } } }] });
  }

  // Every count of every cell.
  function countsTable(s, cells) {
    laterTable(s, ['backend / setting', 'category', 'cases', 'boolean wrong', 'FN', 'FP',
      'all-pairs wrong', 'true pairs', 'missed', 'extra', 'distance wrong', 'no answer'],
    cells.map((c) => {
      const b = c.boolean;
      const p = c.all_pairs;
      const d = c.distance || { status: 'none', failed: 0 };
      const answer = (a) => a.status === 'measured' ? a.wrong + ' / ' + a.answered : a.status;
      const measured = p.status === 'measured';
      return [c.backend, c.category, String(c.cases), answer(b), String(b.false_negatives),
        String(b.false_positives), answer(p), measured ? String(p.true_pairs) : '-',
        measured ? p.missed_pairs + ' (' + pct(p.missed_share) + ')' : '-',
        measured ? p.extra_pairs + ' (' + pct(p.extra_share) + ')' : '-',
        answer(d), String(b.failed + p.failed + d.failed)];
    }), ['', '', 'num', 'num', 'num', 'num', 'num', 'num', 'num', 'num', 'num', 'num']);
  }

  function render(model) {
    const s = section('robustness', 'Robustness matrix',
      'Every backend setting on the stress scenes (scenes/stress/), by robustness category: the ' +
      'share of cases whose answer differs from the exact oracle\'s, for the boolean question ' +
      'and for the set of intersecting triangle pairs. Green is none wrong; grey is a question the ' +
      'backend does not answer (unsupported), brown one it failed to answer (errors, crashed ' +
      'workers): neither is ever shown as zero errors; a pale cell is a question the category ' +
      'does not ask. The tooltip has the counts: false ' +
      'negatives and positives, missed and extra triangle pairs.');
    const cells = model.data.robustness || [];
    if (cells.length === 0) {
      empty(s, 'No stress scene in this study: add scenes/stress/*.json (tools/study.sh does) ' +
        'to measure each backend at the edges.');
      return;
    }
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const kinds = [['boolean', 'Wrong boolean answers'], ['all_pairs', 'Wrong all-pairs answers']];
    // The distance category's answers, held to the exact distance at contact scale.
    if (cells.some((c) => c.distance && c.distance.status !== 'none')) {
      kinds.push(['distance', 'Wrong distance answers (0 for apart, positive for touching, ' +
        'or off by more than 1e-6 of the exact distance)']);
    }
    for (const [kind, title] of kinds) matrixChart(box, cells, kind, title);
    countsTable(s, cells);
  }

  return { render };
})();
