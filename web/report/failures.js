// Failures, wrong answers and gaps: what failed in the run, the queries answered wrongly, the
// queries a backend does not answer by design, and the settings not planned on a scene.
const ReportFailures = (() => {
  'use strict';
  const { el, section, table, laterTable, empty } = ReportDom;
  const { groupBy } = ReportModel;

  const failureTable = (holder, list) => laterTable(holder,
    ['what', 'backend / setting', 'scene', 'query', 'detail'], list.map((f) => {
      const detail = el('div', { text: f.detail });
      if (f.log) detail.appendChild(el('pre', { class: 'log', text: f.log }));
      return [f.what, f.label, f.scene, f.query, detail];
    }), ['bad']);

  function render(model) {
    const { realFailures, wrongAnswers, byDesign, designGaps, notApplicable } = model;
    const s = section('failures', 'Failures, wrong answers and gaps',
      'Three lists: what failed in the run (crashes, timeouts and failed workers, which the study ' +
      'went on without, and queries that failed or whose input was refused), queries with ' +
      'answers that differ from the exact oracle, and the queries some backend does not answer ' +
      'by design, each listed once per backend setting; then the settings not planned on a ' +
      'scene at all, since they answer none of the kinds it asks.');
    // The header's counts link to these parts by their ids.
    const part = (id, title) => {
      const holder = el('div', { id: id, class: 'part' }, [el('h3', { text: title })]);
      s.appendChild(holder);
      return holder;
    };
    const real = part('failures-real', `Failures (${realFailures.length})`);
    if (realFailures.length === 0) empty(real, 'None: every worker finished and every query answered.');
    else failureTable(real, realFailures);
    const wrong = part('wrong-answers', `Wrong answers (${wrongAnswers.length})`);
    if (wrongAnswers.length === 0) empty(wrong, 'None: every answer matched the oracle.');
    else failureTable(wrong, wrongAnswers);
    const design = part('by-design', `Not run by design (${byDesign.length} queries)`);
    if (designGaps.length === 0) empty(design, 'None: every backend answers every query asked.');
    else {
      table(design, ['backend / setting', 'why', 'queries', 'scenes'], designGaps.map((g) => [g.label,
        g.reasons.join('; '), String(byDesign.filter((f) => f.label === g.label).length),
        g.scenes.join(', ')]), ['', '', 'num', '']);
    }
    const notPlanned = part('not-applicable', `Not applicable (${notApplicable.length} setting ` +
      'and scene pairs not planned)');
    if (notApplicable.length === 0) {
      empty(notPlanned, 'None: no setting was left out of a scene as not applicable.');
    } else {
      const groups = [...groupBy(notApplicable, (n) => n.backend).values()];
      table(notPlanned, ['backend / setting', 'why', 'scenes'], groups.map((list) => [list[0].backend,
        [...new Set(list.map((n) => n.why))].join('; '), list.map((n) => n.scene).join(', ')]),
        ['', '', '']);
    }
  }

  return { render };
})();
