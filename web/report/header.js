// The page's header: the summary line, the counts of failures, wrong answers and gaps (each a
// link to its list), the study's measured noise, and the bar of chart filters.
const ReportHeader = (() => {
  'use strict';
  const { fmt } = ReportFormat;
  const { el } = ReportDom;
  const { setFilters } = ReportCharts;

  const link = (href, text, cls) => el('a', { href: href, text: text, class: cls });

  // The counts of failures, wrong answers and queries not run by design (and of settings not
  // planned on a scene, where there are some), each a link to its list in the failures section.
  function counts(model) {
    const { realFailures, wrongAnswers, byDesign, designGaps, notApplicable } = model;
    const line = el('p', { id: 'counts' });
    line.appendChild(link('#failures-real', `${realFailures.length} failures`,
      realFailures.length ? 'count bad' : 'count'));
    line.appendChild(document.createTextNode(' (crash, timeout, refused or failed query) · '));
    line.appendChild(link('#wrong-answers', `${wrongAnswers.length} queries with wrong answers`,
      wrongAnswers.length ? 'count bad' : 'count'));
    line.appendChild(document.createTextNode(' · '));
    line.appendChild(link('#by-design', `${byDesign.length} not run by design`, 'count'));
    line.appendChild(document.createTextNode(` (${designGaps.length} backend settings ` +
      'that do not answer some query kind)'));
    if (notApplicable.length) {
      line.appendChild(document.createTextNode(' · '));
      line.appendChild(link('#not-applicable', `${notApplicable.length} not applicable`, 'count'));
      line.appendChild(document.createTextNode(' (setting and scene pairs not planned)'));
    }
    return line;
  }

  // The study's measured noise: how far apart one setting's rounds (worker processes) came
  // out, and the rows whose rounds disagreed past twice the equivalence band.
  function noise(model) {
    const { ok, pickBand } = model;
    const spreads = ok.map((r) => r.round_spread).filter((v) => typeof v === 'number')
      .sort((a, b) => a - b);
    const at = (q) => spreads[Math.min(spreads.length - 1, Math.floor(q * spreads.length))];
    const unstableRows = ok.filter((r) => r.unstable === true).length;
    return el('p', { id: 'noise', text: spreads.length === 0 ?
      'Measured noise: one round per setting, so the noise between worker processes is not ' +
      'measured (collido study --rounds 3).' :
      `Measured noise: the rounds (worker processes) of one setting came out ${fmt(at(0.5), 2)}x ` +
      `apart at the median, ${fmt(at(0.9), 2)}x at the 90th percentile, over ${spreads.length} ` +
      `rows; ${unstableRows} rows unstable (their rounds cannot pin the figure down to within ` +
      `${fmt(100 * pickBand, 0)}%, even after the extra rounds the study gave them: their figures ` +
      'are suspect, their intervals wide).' });
  }

  function summary(model) {
    const { data, ok } = model;
    const backends = new Set(data.rows.map((r) => r.label));
    const scenes = new Set(data.rows.map((r) => r.scene));
    const line = document.getElementById('summary');
    line.appendChild(document.createTextNode(`${data.title} · ${backends.size} backend settings` +
      ` × ${scenes.size} scenes · ${ok.length} measured queries · generated ${data.generated}`));
    const countsLine = counts(model);
    line.after(countsLine);
    countsLine.after(noise(model));
  }

  // The chart filters, under the table of contents: they select in every filtered chart.
  function filterBar(model) {
    const { data, families } = model;
    const select = (id, options) => el('select', { id: id },
      options.map((o) => el('option', { value: o, text: o })));
    const familyPick = select('filter-family', ['all'].concat(families));
    const queryPick = select('filter-query',
      ['all'].concat([...new Set(data.rows.map((r) => r.kind))].sort()));
    const exactOnly = el('input', { type: 'checkbox', id: 'filter-exact' });
    const bar = el('div', { id: 'filters' }, [el('span', { text: 'Charts: ' }),
      el('label', { text: 'backend family ' }, [familyPick]),
      el('label', { text: 'query ' }, [queryPick]),
      el('label', { text: 'exact only ' }, [exactOnly]),
      el('span', { id: 'filter-count' })]);
    document.getElementById('toc').after(bar);
    const changed = () => setFilters({ family: familyPick.value, query: queryPick.value,
      exact: exactOnly.checked });
    for (const control of [familyPick, queryPick, exactOnly]) control.addEventListener('change', changed);
  }

  return { summary, filterBar };
})();
