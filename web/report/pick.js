// "What to pick": per scene and query, the fastest exact setting, the fastest within the reader's
// budget of wrong frames (or pair recall and precision), and the smallest exact one, as table.txt.
const ReportPick = (() => {
  'use strict';
  const { fmt, ciOf, withInterval } = ReportFormat;
  const { el, section, empty } = ReportDom;
  const { family } = ReportModel;

  const introduction = (statistic, bandText) =>
    'Per scene and query, among the settings that answered every frame: the fastest with no ' +
    'wrong frame, the fastest within the share of wrong frames set here (or, for all pairs, ' +
    'a pair recall and precision set here), and the exact one ' +
    'with the least model memory, each against the best setting of another backend family. ' +
    `Times are the ${statistic}: "mean [low, high]", the brackets its 95% interval. 'vs next' ` +
    'is that other family\'s time over the pick\'s, with its 95% interval paired by frame. ' +
    `A pick is a clear win only when it beats every other setting by more than ${bandText} ` +
    `with 95% confidence. "a ≈ b, c" means the data cannot tell a from b and c beyond ` +
    `${bandText}: a is the fastest by its estimate, but b or c may be as fast; take the one ` +
    'that suits you. Memory is counted, not sampled: there "≈" names the settings within ' +
    `${bandText} of the smallest. The line under each row gives ` +
    'the fastest setting of every family and, where the fastest of all is not exact, what it ' +
    'costs.';

  // --- choosing -------------------------------------------------------------------------------
  const ratio = (a, b) => (a > 0 ? fmt(b / a, 2) + 'x' : '-');
  const perTriangle = (o) => o.bytes_per_triangle;
  // As table.txt counts it: a setting without triangles has 0 bytes per triangle.
  const bytesOf = (o) => perTriangle(o) || 0;
  // `next`'s time over `o`'s with its interval paired by frame, as table.txt prints it (a
  // ratio whose interval is a point alone); null where a time was 0.
  const versus = (o, next) => (o.versus && o.versus[next.backend]) || null;
  const versusText = (v) => (!v ? '-' : v[1] === v[2] ? fmt(v[0], 2) + 'x' :
    `${fmt(v[0], 2)}x [${fmt(v[1], 2)}, ${fmt(v[2], 2)}]`);
  // The best of `admitted` by `better` (ties keep the earlier setting, as table.txt does),
  // the others `tied` to it, best first, and the best of another family.
  const best = (settings, admit, better, tied) => {
    let chosen = null;
    for (const o of settings) if (admit(o) && (!chosen || better(o, chosen))) chosen = o;
    if (!chosen) return null;
    let next = null;
    for (const o of settings) {
      if (admit(o) && family(o.backend) !== family(chosen.backend) && (!next || better(o, next))) {
        next = o;
      }
    }
    // Array sort is stable: settings equally good keep their order, as std::stable_sort.
    const ties = settings.filter((o) => o !== chosen && admit(o) && tied(chosen, o))
      .sort((a, b) => (better(a, b) ? -1 : better(b, a) ? 1 : 0));
    return { chosen: chosen, next: next, ties: ties };
  };
  const faster = (a, b) => a.mean_us < b.mean_us;
  const smaller = (a, b) => bytesOf(a) < bytesOf(b) ||
    (bytesOf(a) === bytesOf(b) && faster(a, b));
  // A time pick ties with every setting it is not clearly faster than (the study decided
  // that from the paired intervals: its `clearly_faster_than`).
  const timeTie = (p, o) => !(p.clearly_faster_than || []).includes(o.backend);
  // Memory is counted: a setting within the band of the pick's bytes ties with it (all do
  // when the pick's is 0, since no ratio says otherwise).
  const memoryTie = (band) => (p, o) => !(bytesOf(p) > 0) || bytesOf(o) / bytesOf(p) <= 1 + band;

  // --- as text --------------------------------------------------------------------------------
  // "obbtree ≈ fcl:obb, bullet", byte for byte as table.txt names a pick and its ties.
  const pickText = (b) => b.chosen.backend +
    (b.ties.length ? ' ≈ ' + b.ties.map((o) => o.backend).join(', ') : '');
  const timeText = (o) => withInterval(o.mean_us, ciOf(o));
  const wrongText = (o) => `${o.wrong_frames} of ${o.frames}`;
  // A pick's cell names it; its title gives every figure of it, its ties and the runner-up.
  const figures = (o) => `${timeText(o)} µs, ${fmt(perTriangle(o), 0)} B/tri, wrong on ` +
    wrongText(o) + (o.recall === null || o.recall === undefined ? '' :
    `, pair recall ${fmt(o.recall, 4)}, precision ${fmt(o.precision, 4)}`);
  const explain = (b, byMemory, bandText) => `${b.chosen.backend}: ${figures(b.chosen)}\n` +
    (b.ties.length ? `ties (not told apart beyond ${bandText}` +
      (byMemory ? ' of memory' : ' at 95% confidence') + '): ' +
      b.ties.map((o) => `${o.backend} ${byMemory ? fmt(perTriangle(o), 0) + ' B/tri' :
        timeText(o) + ' µs'}`).join(', ') :
      `a clear win: ${byMemory ? 'smaller' : 'faster'} than every other setting by more than ` +
      bandText + (byMemory ? '' : ' at 95% confidence')) +
    (b.next ? `\nnext family: ${b.next.backend}: ${figures(b.next)}; its ` +
      (byMemory ? `memory over the pick's ${ratio(perTriangle(b.chosen), perTriangle(b.next))}` :
        `time over the pick's ${versusText(versus(b.chosen, b.next))} (95% interval)`) : '');

  // --- the table ------------------------------------------------------------------------------
  // Under each row: every family's fastest setting, and what the fastest of all costs.
  function familiesRow(p) {
    const perFamily = (p.fastest_per_family || []).map((o) => `${o.backend} ${timeText(o)} µs` +
      (o.wrong_frames ? ` (wrong on ${wrongText(o)})` : '')).join(' · ');
    const detail = el('td', { colspan: '11', class: 'pick-detail' });
    detail.appendChild(el('span', { text: 'fastest per family: ' + perFamily }));
    if (p.cost) detail.appendChild(el('span', { class: 'cost', text: ' — ' + p.cost }));
    return el('tr', { class: 'pick-detail' }, [detail]);
  }
  // The picks with the reader's limits: `allowed` the percentage of wrong frames, `floor` the
  // pair recall and precision held of all pairs instead (a share, or null where unset).
  function picksTable(picks, band, bandText, allowed, floor) {
    const share = Math.max(0, allowed) / 100;
    const withinBudget = (o) => (floor !== null && o.recall !== null && o.recall !== undefined ?
      o.recall >= floor && o.precision >= floor : o.wrong_frames <= share * o.frames);
    const exact = (o) => o.wrong_frames === 0;
    const cell = (text, cls, pick, chosen, byMemory) => el('td', Object.assign({ text: text,
      class: cls || '' }, pick ? { 'data-pick': pick } : {},
    chosen ? { title: explain(chosen, byMemory, bandText) } : {}));
    const header = el('tr', {}, ['scene', 'query', 'fastest exact', 'µs [95% CI]', 'vs next',
      `fastest within ${fmt(allowed, 0)}% wrong` + (floor === null ? '' :
        ` (all pairs: ≥ ${fmt(100 * floor, 1)}% recall and precision)`), 'µs [95% CI]',
      'wrong frames', 'smallest exact', 'B/tri', 'vs next'].map((h) => el('th', { text: h })));
    const t = el('table', { class: 'picks' }, [header]);
    for (const p of picks) {
      const f = best(p.settings, exact, faster, timeTie);
      const w = best(p.settings, withinBudget, faster, timeTie);
      const m = best(p.settings, exact, smaller, memoryTie(band));
      const scene = p.resolution === 1 ? p.scene : `${p.scene} r=${p.resolution}`;
      t.appendChild(el('tr', { class: 'pick', 'data-scene': scene, 'data-query': p.query }, [
        cell(scene), cell(p.query),
        cell(f ? pickText(f) : 'none exact', '', 'fastest-exact', f),
        cell(f ? timeText(f.chosen) : '-', 'num'),
        cell(f && f.next ? versusText(versus(f.chosen, f.next)) : '-', 'num'),
        cell(w ? pickText(w) : 'none', '', 'fastest-within', w),
        cell(w ? timeText(w.chosen) : '-', 'num'), cell(w ? wrongText(w.chosen) : '-', 'num'),
        cell(m ? pickText(m) : 'none exact', '', 'smallest-exact', m, true),
        cell(m ? fmt(perTriangle(m.chosen), 0) : '-', 'num'),
        cell(m && m.next ? ratio(perTriangle(m.chosen), perTriangle(m.next)) : '-', 'num')]));
      t.appendChild(familiesRow(p));
    }
    return t;
  }

  function render(model) {
    const { data, pickBand: band } = model;
    const wanted = data.what_to_pick || {};
    const bandText = fmt(100 * band, 0) + '%';
    const statistic = (wanted.statistic ||
      'mean over frames of each frame\'s median call (us per query)').replace('(us per', '(µs per');
    const s = section('what-to-pick', 'What to pick', introduction(statistic, bandText));
    const picks = wanted.picks || [];
    if (picks.length === 0) {
      empty(s, 'No scene with a setting that answered every frame.');
      return;
    }
    const budget = el('input', { type: 'number', min: '0', max: '100', step: '1',
      value: String(100 * data.what_to_pick.budget.wrong_frame_share), id: 'pick-budget' });
    // All pairs may instead be held to the pairs: a frame missing one pair of thousands is
    // "wrong", and a reader may accept that.
    const pairFloor = el('input', { type: 'number', min: '0', max: '100', step: '0.1',
      placeholder: 'unset', id: 'pick-pair-floor' });
    s.appendChild(el('div', { class: 'budget' }, [
      el('label', { text: 'wrong frames allowed (%) ' }, [budget]),
      el('label', { text: 'all pairs instead: pair recall and precision at least (%) ' },
        [pairFloor])]));
    const holder = el('div', { class: 'table-scroll' });
    s.appendChild(holder);
    const floorValue = () => (pairFloor.value === '' ? null :
      Math.min(100, Math.max(0, Number(pairFloor.value))) / 100);
    const update = () => {
      holder.textContent = '';
      holder.appendChild(picksTable(picks, band, bandText, Number(budget.value) || 0,
        floorValue()));
    };
    budget.addEventListener('input', update);
    pairFloor.addEventListener('input', update);
    update();
  }

  return { render };
})();
