// Collidoscope's dashboard: builds the views of `collido report` from the study data inlined in
// the page, with Vega-Lite. A chart is drawn when it comes near the window (a full study has
// hundreds); COLLIDO_REPORT.renderAll() draws every one. Each chart container gets
// data-rendered="true" once drawn (or data-error with the reason), which the browser test checks;
// the body gets data-ready="true" once the charts in view are drawn.
(function () {
  'use strict';
  const data = JSON.parse(document.getElementById('collido-data').textContent);
  const views = document.getElementById('views');
  const toc = document.getElementById('toc');
  const drawing = [];
  const waiting = new Map();
  const near = 'IntersectionObserver' in window ? new IntersectionObserver((entries) => {
    for (const entry of entries) if (entry.isIntersecting) draw(entry.target);
  }, { rootMargin: '600px 0px' }) : null;
  function draw(holder) {
    const start = waiting.get(holder);
    if (!start) return;
    waiting.delete(holder);
    if (near) near.unobserve(holder);
    drawing.push(start());
  }
  window.COLLIDO_REPORT = { ready: null, errors: [],
    renderAll: () => {
      for (const holder of [...waiting.keys()]) draw(holder);
      return Promise.all(drawing);
    } };

  // --- helpers --------------------------------------------------------------------------------
  function el(tag, attrs, children) {
    const node = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === 'text') node.textContent = v;
      else node.setAttribute(k, v);
    }
    for (const child of children || []) node.appendChild(child);
    return node;
  }
  function section(id, title, explain) {
    const s = el('section', { class: 'view', id: id }, [
      el('h2', { text: title }), el('p', { class: 'explain', text: explain })]);
    views.appendChild(s);
    toc.appendChild(el('a', { href: '#' + id, text: title }));
    return s;
  }
  function chart(parent, name, spec, onView) {
    const holder = el('div', { class: 'chart', 'data-view': name });
    parent.appendChild(holder);
    spec.$schema = 'https://vega.github.io/schema/vega-lite/v6.json';
    // Labels that would touch are dropped (with no gap, "2,000" and "3,000" read "2,0003,000").
    spec.config = Object.assign({ font: 'system-ui, sans-serif',
      axis: { labelFontSize: 11, labelOverlap: 'greedy', labelSeparation: 6 } }, spec.config || {});
    tidyLogAxes(spec);
    holder.classList.add('waiting');
    waiting.set(holder, () => {
      // Data too large to build for every chart up front is built when the chart is drawn.
      if (spec.data && typeof spec.data.values === 'function') spec.data.values = spec.data.values();
      // Drawn late: it starts from the filters as they are now.
      for (const param of spec.params || []) {
        if (param.name in filterParamOf) param.value = filterState[filterParamOf[param.name]];
      }
      return vegaEmbed(holder, spec, { actions: { export: true, source: false, compiled: false,
        editor: false }, renderer: 'svg' })
        .then((result) => {
          holder.classList.remove('waiting');
          holder.setAttribute('data-rendered', 'true');
          if (onView) onView(result.view);
        })
        .catch((e) => {
          holder.setAttribute('data-error', String(e));
          window.COLLIDO_REPORT.errors.push(name + ': ' + e);
          console.error('chart ' + name + ' failed: ' + e);
        });
    });
    if (near) near.observe(holder); else draw(holder);
    return holder;
  }
  // Log axes tick every power's multiples; only 1, 2 and 5 times a power are labelled, in
  // short form ("2000", "0.5"), and greedy dropping keeps those apart.
  const LOG_LABEL = 'indexof([1, 2, 5], round(datum.value / pow(10, floor(log(datum.value) / ' +
    "LN10 + 1e-9)))) >= 0 ? format(datum.value, '~g') : ''";
  function tidyLogAxes(node) {
    if (Array.isArray(node)) { node.forEach(tidyLogAxes); return; }
    if (!node || typeof node !== 'object') return;
    if (node.scale && node.scale.type === 'log' && node.field && node.axis !== null) {
      node.axis = Object.assign({ labelExpr: LOG_LABEL, labelOverlap: 'greedy',
        labelSeparation: 6 }, node.axis || {});
    }
    for (const key of Object.keys(node)) {
      if (key !== 'data') tidyLogAxes(node[key]);
    }
  }
  // A table of many rows is built when it comes near the window (COLLIDO_REPORT.renderAll()
  // builds it too): thousands of rows would hold up the first screen.
  function laterTable(parent, header, rows, classes) {
    if (rows.length < 200) return table(parent, header, rows, classes);
    const holder = el('div', { class: 'waiting-table', text: `${rows.length} rows` });
    parent.appendChild(holder);
    waiting.set(holder, () => {
      holder.textContent = '';
      holder.classList.remove('waiting-table');
      table(holder, header, rows, classes);
      return Promise.resolve();
    });
    if (near) near.observe(holder); else draw(holder);
    return holder;
  }
  function table(parent, header, rows, classes) {
    const t = el('table');
    t.appendChild(el('tr', {}, header.map((h) => el('th', { text: h }))));
    for (const row of rows) {
      t.appendChild(el('tr', {}, row.map((cell, i) => {
        const td = el('td', { class: (classes && classes[i]) || '' });
        if (cell instanceof Node) td.appendChild(cell); else td.textContent = cell;
        return td;
      })));
    }
    parent.appendChild(t);
    return t;
  }
  function empty(parent, text) { parent.appendChild(el('p', { class: 'empty', text: text })); }
  // printf's "%.Nf", which table.txt prints with: toFixed rounds a value exactly halfway up
  // (12.25 to "12.3"), printf to even ("12.2"). toFixed(100) gives every decimal of the double.
  const fixed = (x, digits) => {
    if (!Number.isFinite(x) || Math.abs(x) >= 1e21) return String(x);
    const exact = Math.abs(x).toFixed(100);
    const cut = exact.indexOf('.') + 1 + digits;
    if (!/^50*$/.test(exact.slice(cut))) return x.toFixed(digits);
    const kept = exact.slice(0, digits === 0 ? cut - 1 : cut);
    if (Number(kept[kept.length - 1]) % 2 !== 0) return x.toFixed(digits);
    return (x < 0 ? '-' : '') + kept;
  };
  // "-0.00" reads as a finding; a value that rounds to zero is shown as zero.
  const fmt = (x, digits) => {
    if (x === null || x === undefined || Number.isNaN(x)) return '-';
    const d = digits === undefined ? 1 : digits;
    const text = fixed(Number(x), d);
    return Number(text) === 0 ? (0).toFixed(d) : text;
  };
  // The study's one time statistic: the mean over frames of each frame's median call, with its
  // 95% bootstrap interval. A row written before it (an old baseline) has its median call alone.
  const timeOf = (r) => (typeof r.time_us === 'number' ? r.time_us : r.median_us);
  const ciOf = (r) => (Array.isArray(r.ci95_us) && r.ci95_us.length === 2 &&
    r.ci95_us.every((v) => typeof v === 'number' && Number.isFinite(v)) ? r.ci95_us : null);
  // "133.9 [130.2, 137.5]", as table.txt prints a time (withInterval); the time alone without one.
  const withInterval = (value, ci) => fmt(value) + (ci ? ` [${fmt(ci[0])}, ${fmt(ci[1])}]` : '');
  // A chart's time fields: the statistic, and its interval's ends for the whiskers. A log axis
  // cannot show 0, and a whisker reaching down decades would squeeze every point into a corner:
  // the low end is cut at a tenth of the time (the tooltip gives the interval itself). Without
  // an interval the whisker is the point itself.
  const timeFields = (r) => {
    const time = timeOf(r);
    const ci = ciOf(r);
    const lo = Math.max(ci ? ci[0] : time, time / 10, 1e-3);
    return { time_us: time, ci_lo_us: lo, ci_hi_us: Math.max(ci ? ci[1] : time, lo),
      time_ci95: ci ? `[${fmt(ci[0])}, ${fmt(ci[1])}]` : '-' };
  };
  const TIME_TITLE = 'mean time per query (µs), 95% CI';
  // Two times within this share of each other are practically the same (docs/STUDY.md).
  const pickBand = data.what_to_pick && typeof data.what_to_pick.equivalence_band === 'number' ?
    data.what_to_pick.equivalence_band : 0.1;
  const ok = data.rows.filter((r) => r.status === 'ok');
  // Settings run with needs "changed" time only the pairs they asked (a reused frame times at 0):
  // their times are not comparable with the others', so they are shown in the needs section only.
  const charted = ok.filter((r) => r.needs !== 'changed');
  const groupBy = (items, key) => {
    const map = new Map();
    for (const item of items) {
      const k = key(item);
      if (!map.has(k)) map.set(k, []);
      map.get(k).push(item);
    }
    return map;
  };
  // --- backend families, chart filters --------------------------------------------------------
  // A study may hold a hundred settings: charts colour by backend family (a handful), tell the
  // settings of one family apart by shape, and name them in tooltips and on the Pareto front.
  const family = (backend) => String(backend).split(/[:[]/)[0];
  const families = [...new Set(data.rows.map((r) => family(r.backend)))].sort();
  const familyColour = { field: 'family', type: 'nominal', title: 'backend family',
    scale: { domain: families, scheme: 'tableau10' } };
  const SHAPES = ['circle', 'square', 'triangle-up', 'diamond', 'cross', 'triangle-down',
    'triangle-left', 'triangle-right', 'wedge', 'arrow', 'stroke', 'triangle'];
  const markerOf = new Map();
  for (const f of families) {
    const labels = [...new Set(data.rows.filter((r) => family(r.backend) === f).map((r) => r.label))]
      .sort();
    labels.forEach((label, i) => markerOf.set(label, SHAPES[i % SHAPES.length]));
  }
  // The same colours everywhere; each legend lists only the families its chart shows.
  const familyColourOf = (values) => Object.assign({}, familyColour, { legend: {
    values: families.filter((f) => values.some((v) => v.family === f)) } });
  // The shape names themselves (no scale, no legend): the tooltip names the setting.
  const settingShape = { field: 'marker', type: 'nominal', scale: null, legend: null };
  const rowOf = new Map(data.rows.map((r) => [r.label + '|' + r.scene + '|' + r.query, r]));
  // What the filters read from a chart's datum: its family, the query kinds it covers
  // (",boolean,distance,") and whether it is exact on every frame.
  const tagged = (item, fam, rows) => Object.assign({}, item, { family: fam,
    marker: markerOf.get(item.label) || 'circle',
    kinds: ',' + [...new Set(rows.map((r) => r.kind))].join(',') + ',',
    exact: rows.length > 0 && rows.every((r) => r.status === 'ok' && r.disagreements === 0) });
  const tagRow = (r) => Object.assign(tagged(r, family(r.backend), [r]), timeFields(r));
  const tagByLookup = (item) => {
    const r = rowOf.get(item.label + '|' + item.scene + '|' + item.query);
    return tagged(item, family(r ? r.backend : item.label), r ? [r] : []);
  };
  const filterState = { family: 'all', query: 'all', exact: false };
  const filterParamOf = { family_pick: 'family', query_pick: 'query', exact_only: 'exact' };
  const keeps = (d) => (filterState.family === 'all' || d.family === filterState.family) &&
    (filterState.query === 'all' || d.kinds.includes(',' + filterState.query + ',')) &&
    (!filterState.exact || d.exact);
  const FILTER_PARAMS = () => [{ name: 'family_pick', value: 'all' },
    { name: 'query_pick', value: 'all' }, { name: 'exact_only', value: false }];
  const FILTER = "(family_pick === 'all' || datum.family === family_pick) && " +
    "(query_pick === 'all' || indexof(datum.kinds, ',' + query_pick + ',') >= 0) && " +
    '(!exact_only || datum.exact)';
  const filterable = [];
  // A chart whose `values` the filters select: its spec gets the parameters and a first
  // transform; a chart left with nothing to show is hidden.
  function filteredChart(parent, name, spec, values) {
    spec.params = FILTER_PARAMS().concat(spec.params || []);
    spec.transform = [{ filter: FILTER }].concat(spec.transform || []);
    const entry = { values: values, view: null };
    entry.holder = chart(parent, name, spec, (view) => { entry.view = view; });
    filterable.push(entry);
    return entry.holder;
  }
  function applyFilters() {
    let shown = 0;
    for (const entry of filterable) {
      const any = entry.values.some(keeps);
      entry.holder.style.display = any ? '' : 'none';
      if (any) shown += 1;
      // A hidden chart keeps its last selection: an empty one would warn of an empty domain.
      if (any && entry.view) {
        entry.view.signal('family_pick', filterState.family).signal('query_pick', filterState.query)
          .signal('exact_only', filterState.exact).runAsync();
      }
    }
    const count = document.getElementById('filter-count');
    if (count) count.textContent = `${shown} of ${filterable.length} filtered charts shown`;
  }

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

  // --- summary line ---------------------------------------------------------------------------
  // Three counts that mean different things: what went wrong in the run, what a backend answered
  // wrongly, and what a backend was never asked because it does not answer that query at all.
  const backends = new Set(data.rows.map((r) => r.label));
  const scenes = new Set(data.rows.map((r) => r.scene));
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
  {
    const summary = document.getElementById('summary');
    const link = (href, text, cls) => el('a', { href: href, text: text, class: cls });
    summary.appendChild(document.createTextNode(`${data.title} · ${backends.size} backend settings` +
      ` × ${scenes.size} scenes · ${ok.length} measured queries · generated ${data.generated}`));
    const counts = el('p', { id: 'counts' });
    counts.appendChild(link('#failures-real', `${realFailures.length} failures`,
      realFailures.length ? 'count bad' : 'count'));
    counts.appendChild(document.createTextNode(' (crash, timeout, refused or failed query) · '));
    counts.appendChild(link('#wrong-answers', `${wrongAnswers.length} queries with wrong answers`,
      wrongAnswers.length ? 'count bad' : 'count'));
    counts.appendChild(document.createTextNode(' · '));
    counts.appendChild(link('#by-design', `${byDesign.length} not run by design`, 'count'));
    counts.appendChild(document.createTextNode(` (${designGaps.length} backend settings ` +
      'that do not answer some query kind)'));
    if (notApplicable.length) {
      counts.appendChild(document.createTextNode(' · '));
      counts.appendChild(link('#not-applicable', `${notApplicable.length} not applicable`, 'count'));
      counts.appendChild(document.createTextNode(' (setting and scene pairs not planned)'));
    }
    summary.after(counts);
    // The study's measured noise: how far apart one setting's rounds (worker processes) came
    // out, and the rows whose rounds disagreed past twice the equivalence band.
    const spreads = ok.map((r) => r.round_spread).filter((v) => typeof v === 'number')
      .sort((a, b) => a - b);
    const at = (q) => spreads[Math.min(spreads.length - 1, Math.floor(q * spreads.length))];
    const unstableRows = ok.filter((r) => r.unstable === true).length;
    counts.after(el('p', { id: 'noise', text: spreads.length === 0 ?
      'Measured noise: one round per setting, so the noise between worker processes is not ' +
      'measured (collido study --rounds 3).' :
      `Measured noise: the rounds (worker processes) of one setting came out ${fmt(at(0.5), 2)}x ` +
      `apart at the median, ${fmt(at(0.9), 2)}x at the 90th percentile, over ${spreads.length} ` +
      `rows; ${unstableRows} rows unstable (their rounds cannot pin the figure down to within ` +
      `${fmt(100 * pickBand, 0)}%, even after the extra rounds the study gave them: their figures ` +
      'are suspect, their intervals wide).' }));
  }

  // --- chart filters ----------------------------------------------------------------------------
  {
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
    toc.after(bar);
    const changed = () => {
      filterState.family = familyPick.value;
      filterState.query = queryPick.value;
      filterState.exact = exactOnly.checked;
      applyFilters();
    };
    for (const control of [familyPick, queryPick, exactOnly]) control.addEventListener('change', changed);
  }

  // --- 0. what to pick ------------------------------------------------------------------------
  {
    const wanted = data.what_to_pick || {};
    const band = pickBand;
    const bandText = fmt(100 * band, 0) + '%';
    const statistic = (wanted.statistic ||
      'mean over frames of each frame\'s median call (us per query)').replace('(us per', '(µs per');
    const s = section('what-to-pick', 'What to pick',
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
      'costs.');
    const picks = wanted.picks || [];
    if (picks.length === 0) {
      empty(s, 'No scene with a setting that answered every frame.');
    } else {
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
      const memoryTie = (p, o) => !(bytesOf(p) > 0) || bytesOf(o) / bytesOf(p) <= 1 + band;
      // "obbtree ≈ fcl:obb, bullet", byte for byte as table.txt names a pick and its ties.
      const pickText = (b) => b.chosen.backend +
        (b.ties.length ? ' ≈ ' + b.ties.map((o) => o.backend).join(', ') : '');
      const timeText = (o) => withInterval(o.mean_us, ciOf(o));
      const wrongText = (o) => `${o.wrong_frames} of ${o.frames}`;
      // A pick's cell names it; its title gives every figure of it, its ties and the runner-up.
      const figures = (o) => `${timeText(o)} µs, ${fmt(perTriangle(o), 0)} B/tri, wrong on ` +
        wrongText(o) + (o.recall === null || o.recall === undefined ? '' :
        `, pair recall ${fmt(o.recall, 4)}, precision ${fmt(o.precision, 4)}`);
      const explain = (b, byMemory) => `${b.chosen.backend}: ${figures(b.chosen)}\n` +
        (b.ties.length ? `ties (not told apart beyond ${bandText}` +
          (byMemory ? ' of memory' : ' at 95% confidence') + '): ' +
          b.ties.map((o) => `${o.backend} ${byMemory ? fmt(perTriangle(o), 0) + ' B/tri' :
            timeText(o) + ' µs'}`).join(', ') :
          `a clear win: ${byMemory ? 'smaller' : 'faster'} than every other setting by more than ` +
          bandText + (byMemory ? '' : ' at 95% confidence')) +
        (b.next ? `\nnext family: ${b.next.backend}: ${figures(b.next)}; its ` +
          (byMemory ? `memory over the pick's ${ratio(perTriangle(b.chosen), perTriangle(b.next))}` :
            `time over the pick's ${versusText(versus(b.chosen, b.next))} (95% interval)`) : '');
      const cell = (text, cls, pick, chosen, byMemory) => el('td', Object.assign({ text: text,
        class: cls || '' }, pick ? { 'data-pick': pick } : {},
      chosen ? { title: explain(chosen, byMemory) } : {}));
      const floorValue = () => (pairFloor.value === '' ? null :
        Math.min(100, Math.max(0, Number(pairFloor.value))) / 100);
      const header = () => el('tr', {}, ['scene', 'query', 'fastest exact', 'µs [95% CI]', 'vs next',
        `fastest within ${fmt(Number(budget.value) || 0, 0)}% wrong` + (floorValue() === null ? '' :
          ` (all pairs: ≥ ${fmt(100 * floorValue(), 1)}% recall and precision)`), 'µs [95% CI]',
        'wrong frames', 'smallest exact', 'B/tri', 'vs next'].map((h) => el('th', { text: h })));
      const render = () => {
        const share = Math.max(0, Number(budget.value) || 0) / 100;
        const floor = floorValue();
        const withinBudget = (o) => (floor !== null && o.recall !== null && o.recall !== undefined ?
          o.recall >= floor && o.precision >= floor : o.wrong_frames <= share * o.frames);
        holder.textContent = '';
        const t = el('table', { class: 'picks' }, [header()]);
        for (const p of picks) {
          const exact = (o) => o.wrong_frames === 0;
          const f = best(p.settings, exact, faster, timeTie);
          const w = best(p.settings, withinBudget, faster, timeTie);
          const m = best(p.settings, exact, smaller, memoryTie);
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
          // Under each row: every family's fastest setting, and what the fastest of all costs.
          const perFamily = (p.fastest_per_family || []).map((o) => `${o.backend} ${timeText(o)} µs` +
            (o.wrong_frames ? ` (wrong on ${wrongText(o)})` : '')).join(' · ');
          const detail = el('td', { colspan: '11', class: 'pick-detail' });
          detail.appendChild(el('span', { text: 'fastest per family: ' + perFamily }));
          if (p.cost) detail.appendChild(el('span', { class: 'cost', text: ' — ' + p.cost }));
          t.appendChild(el('tr', { class: 'pick-detail' }, [detail]));
        }
        holder.appendChild(t);
      };
      budget.addEventListener('input', render);
      pairFloor.addEventListener('input', render);
      render();
    }
  }

  // --- 1. time against error ------------------------------------------------------------------
  {
    const s = section('time-vs-error', 'Run time against error',
      'One point per backend setting: its time per query (log scale), the mean over frames of ' +
      'each frame\'s median call, whiskers its 95% interval, against the share of ' +
      'frames whose answer differs from the exact oracle. Colour is the backend family, shape ' +
      'the setting within it (named in the tooltip). The dashed line joins the Pareto front, ' +
      'the settings no other one beats on both, each named beside its point; it follows the ' +
      'filters above. Points at 0% are exact on every frame of the scene.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const groups = groupBy(charted, (r) => r.scene + ' · ' + r.query);
    if (groups.size === 0) empty(s, 'No measured query.');
    for (const [name, rows] of groups) {
      const points = rows.map(tagRow);
      const top = Math.max(0.05, ...points.map((p) => p.error_rate || 0));
      const x = { field: 'time_us', type: 'quantitative', scale: { type: 'log' }, title: TIME_TITLE };
      // The whiskers share the time axis: the same scale and title, or Vega-Lite would join two.
      const whisker = { x: Object.assign({}, x, { field: 'ci_lo_us' }), x2: { field: 'ci_hi_us' } };
      const colour = familyColourOf(points);
      // At least 0-5%: a scene where every setting is exact shows a 0% axis, not a single
      // "0.000000" tick; exact points sit on the 0% line.
      const y = { field: 'error_rate', type: 'quantitative', title: 'share of frames wrong',
        scale: { domain: [0, top] }, axis: { format: '.0%' } };
      filteredChart(box, 'time-vs-error:' + name, {
        title: name, width: 360, height: 220, data: { values: points },
        // The Pareto front of what the filters leave: in order of time, a point is on it when
        // its error is below that of every faster point.
        transform: [
          { window: [{ op: 'min', field: 'error_rate', as: 'best_before' }],
            sort: [{ field: 'time_us' }, { field: 'error_rate' }], frame: [null, -1],
            ignorePeers: true },
          { calculate: '!isValid(datum.best_before) || datum.error_rate < datum.best_before',
            as: 'on_front' }],
        encoding: { x: x, y: y },
        layer: [
          { transform: [{ filter: 'datum.on_front' }],
            mark: { type: 'line', interpolate: 'step-after', color: '#666', strokeDash: [4, 3] } },
          { mark: { type: 'rule', opacity: 0.7, strokeWidth: 1.5 }, encoding: Object.assign({ color: colour }, whisker) },
          { mark: { type: 'point', filled: true, size: 70, opacity: 0.85 },
            encoding: { color: colour, shape: settingShape,
              tooltip: [{ field: 'label', title: 'setting' },
                { field: 'time_us', title: 'mean µs', format: '.1f' },
                { field: 'time_ci95', title: '95% CI (µs)' },
                { field: 'p99_us', title: 'call p99 µs', format: '.1f' },
                { field: 'error_rate', format: '.3f' },
                { field: 'recall', format: '.4f' }, { field: 'precision', format: '.4f' },
                { field: 'finest_error_rate', format: '.3f' }] } },
          { transform: [{ filter: 'datum.on_front' }],
            mark: { type: 'text', align: 'left', dx: 7, dy: -7, fontSize: 10, color: '#333' },
            encoding: { text: { field: 'label' } } }] }, points);
    }
  }

  // The time (log, whiskers its 95% interval) against an error on a symlog scale: linear below
  // 1e-16, logarithmic above, so an answer exact to the last bit sits on the 0 line instead of
  // at an invented floor. The chart the distance and contact sections share.
  function timeAgainstErrorChart(box, name, points, error, title, tooltip) {
    const values = points.map((p) => Object.assign(tagRow(p), { shown_error: Math.max(error(p) || 0, 0) }));
    // Powers of ten from 1e-16 to the first above every error (every other one past seven).
    const largest = Math.max(...values.map((v) => v.shown_error));
    let powers = [];
    for (let e = -16; e <= 0 && (powers.length === 0 || powers[powers.length - 1] < largest); ++e) {
      powers.push(Number('1e' + e));
    }
    if (powers.length > 7) powers = powers.filter((_, i) => (powers.length - 1 - i) % 2 === 0);
    const top = Math.max(powers[powers.length - 1], largest);
    const ticks = [0].concat(powers);
    const x = { field: 'time_us', type: 'quantitative', scale: { type: 'log' }, title: TIME_TITLE };
    filteredChart(box, name, {
      title: name.slice(name.indexOf(':') + 1), width: 360, height: 220,
      data: { values: values },
      encoding: {
        x: x,
        y: { field: 'shown_error', type: 'quantitative', title: title,
          scale: { type: 'symlog', constant: 1e-16, domain: [0, top] },
          axis: { values: ticks, format: '~g', labelOverlap: 'greedy' } },
        color: familyColourOf(values) },
      layer: [
        // The whiskers share the time axis: the same scale and title, or Vega-Lite would join two.
        { mark: { type: 'rule', opacity: 0.7, strokeWidth: 1.5 },
          encoding: { x: Object.assign({}, x, { field: 'ci_lo_us' }), x2: { field: 'ci_hi_us' } } },
        { mark: { type: 'point', filled: true, size: 70, opacity: 0.85 },
          encoding: { shape: settingShape,
            tooltip: [{ field: 'label', title: 'setting' },
              { field: 'time_us', title: 'mean µs', format: '.1f' },
              { field: 'time_ci95', title: '95% CI (µs)' }].concat(tooltip) } }] }, values);
  }

  // --- 1b. distances: run time against distance error -----------------------------------------
  {
    const s = section('distance-error', 'Distances: run time against error',
      'Distance queries only: time per query (log scale; the mean over frames of each frame\'s ' +
      'median call, whiskers its 95% interval) against the largest error of ' +
      'the reported distance over the frames, relative to the exact distance (symlog scale: ' +
      'linear below 1e-16, so an answer exact to the last bit is drawn at 0). The share of wrong frames (time against ' +
      'error above) also counts closest points that do not hold together.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const rows = charted.filter((r) => r.kind === 'distance' && r.max_distance_error !== null &&
      r.max_distance_error !== undefined);
    const groups = groupBy(rows, (r) => r.scene + ' · ' + r.query);
    if (groups.size === 0) empty(s, 'No measured distance query.');
    for (const [name, points] of groups) {
      timeAgainstErrorChart(box, 'distance-error:' + name, points,
        (p) => (p.max_relative_distance_error === null ? p.max_distance_error :
          p.max_relative_distance_error), 'largest relative distance error',
        [{ field: 'max_distance_error', format: '.3g' },
          { field: 'max_relative_distance_error', format: '.3g' },
          { field: 'error_rate', format: '.3f' }]);
    }
  }

  // --- 1c. contacts: run time against contact error ------------------------------------------
  {
    const s = section('contact-error', 'Contacts: run time against contact error',
      'Contacts queries only, each contact held to the exact contact of its triangle pair ' +
      '(docs/DESIGN.md, "Contact geometry"): time per query (log scale; the mean over frames of ' +
      'each frame\'s median call, whiskers its 95% interval) against the ' +
      'largest distance of a contact point to its pair\'s exact intersection set (symlog ' +
      'scale: linear below 1e-16, so an exact point is drawn at 0). The table gives every contact figure.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const rows = charted.filter((r) => r.kind === 'contacts' && r.contacts_per_frame !== null &&
      r.contacts_per_frame !== undefined);
    const groups = groupBy(rows, (r) => r.scene + ' · ' + r.query);
    if (groups.size === 0) empty(s, 'No measured contacts query.');
    const figure = (v, digits) => (v === null || v === undefined ? '-' : v.toPrecision(digits));
    const lines = [];
    for (const [name, points] of groups) {
      timeAgainstErrorChart(box, 'contact-error:' + name, points,
        (p) => p.contact_position_error, 'largest contact point error',
        [{ field: 'contacts_per_frame', format: '.1f' },
          { field: 'contact_position_error', format: '.3g' },
          { field: 'contact_normal_error_deg', format: '.3g' },
          { field: 'contact_depth_error', format: '.3g' },
          { field: 'contact_coverage', format: '.3f' },
          { field: 'contact_false_pairs' }]);
      for (const p of points) {
        lines.push([name, p.label, withInterval(timeOf(p), ciOf(p)), figure(p.contacts_per_frame, 3),
          figure(p.contact_position_error, 3), figure(p.contact_surface_error, 3),
          figure(p.contact_normal_error_deg, 3), figure(p.contact_depth_error, 3),
          p.contact_coverage === null ? '-' : (100 * p.contact_coverage).toFixed(1) + '%',
          String(p.contact_false_pairs)]);
      }
    }
    if (lines.length > 0) {
      laterTable(s, ['scene · query', 'backend / setting', 'mean µs [95% CI]', 'contacts/frame', 'point err',
        'surface err', 'normal °', 'depth err', 'coverage', 'false pairs'], lines);
    }
  }

  // --- NURBS surfaces: run time against error (collido surface-distance files) ---------------
  {
    const s = section('surfaces', 'NURBS surfaces: run time against error',
      'From the study\'s surface files (collido study --surfaces FILE, each backend in a ' +
      'worker of its own; or collido report --surface-distance F with a collido ' +
      'surface-distance --json file; tools/study.sh runs every scenes/surfaces file): per surface pair, each backend\'s median ' +
      'time per distance query against its error, measured from the middle of the seed ' +
      'method\'s certified interval (1e-10 of the model\'s size wide), relative to the model\'s ' +
      'size (log scales; an error below 1e-16 is drawn at 1e-16). Surface backends (the seed as ' +
      'nurbs:*, OpenCASCADE as occt:*) answer on the surfaces; mesh backends on tessellations ' +
      '(the label gives the segments per parameter; the tooltip the build time). Below each ' +
      'chart, the seed method\'s work with hull and with box bounds, and the failures.');
    const comparisons = data.surfaces || [];
    if (comparisons.length === 0) empty(s, 'No surface comparison in this study (collido ' +
      'study ... --surfaces FILE, or collido report DIR --surface-distance F).');
    // One colour per backend across every chart.
    const surfaceBackends = [...new Set(comparisons.flatMap((c) => c.backends.map((b) => b.backend)))]
      .sort();
    for (const c of comparisons) {
      const name = (c.name || c.file) + ': ' + c.a + ' · ' + c.b;
      const box = el('div', { class: 'charts' });
      s.appendChild(box);
      const answered = c.backends.filter((b) => b.status === 'ok');
      const values = answered.map((b) => Object.assign({}, b, {
        label: b.segments > 0 ? b.backend + ' @' + b.segments : b.backend,
        shape: b.segments > 0 ? 'tessellation' : 'surfaces',
        relative_error: Math.max(Math.abs(b.error) / c.model_size, 1e-16) }));
      if (values.length > 0) {
        chart(box, 'surfaces:' + name, {
          title: name, width: 420, height: 240, data: { values: values },
          mark: { type: 'point', filled: true, size: 80 },
          encoding: {
            x: { field: 'median_us', type: 'quantitative', scale: { type: 'log' },
              title: 'median time per query (µs)', axis: { format: '~s', labelOverlap: 'greedy' } },
            y: { field: 'relative_error', type: 'quantitative', scale: { type: 'log' },
              title: '|error| / model size' },
            color: { field: 'backend', type: 'nominal', title: 'backend',
              scale: { domain: surfaceBackends } },
            shape: { field: 'shape', type: 'nominal', title: 'answers on' },
            tooltip: [{ field: 'label', title: 'backend' }, { field: 'distance', format: '.12g' },
              { field: 'error', format: '.3g' }, { field: 'median_us', format: '.1f' },
              { field: 'triangles' }, { field: 'build_ms', title: 'build ms', format: '.2f' }] } });
      } else {
        empty(box, name + ': no backend answered.');
      }
      const seeds = (c.seed || []).map((r) => [r.bound + (r.descent ? ' + descent' : ' (seed)'),
        r.lower.toPrecision(12), r.upper.toPrecision(12), (r.upper - r.lower).toPrecision(2),
        r.converged ? 'yes' : 'no', String(r.pairs_bounded), String(r.levels.length),
        fmt(r.median_ms, 3)]);
      if (seeds.length > 0) {
        table(s, ['bound', 'lower', 'upper', 'gap', 'converged', 'pairs bounded', 'levels',
          'median ms'], seeds);
      }
      const failed = c.backends.filter((b) => b.status !== 'ok');
      const problems = (c.problems || []).map((p) => el('li', { text: p }));
      if (failed.length + problems.length > 0) {
        s.appendChild(el('ul', {}, problems.concat(failed.map((b) => el('li', { text: b.backend +
          (b.segments > 0 ? ' @' + b.segments : '') + ': ' + b.status })))));
      }
    }
  }

  // --- FRep solids: guaranteed collision against polygonization (collido frep files) ------------
  {
    const s = section('frep', 'FRep solids: run time against error',
      'From the study\'s FRep files (collido study --frep FILE, each backend in a worker of ' +
      'its own; or collido report --frep F with a collido frep --json file; tools/study.sh runs every ' +
      'scenes/frep file): per FRep file, the seed method\'s guaranteed octree test (frep:octree, ' +
      'never wrong: its answers are the reference) against mesh backends on OpenVDB ' +
      'polygonizations at several grid resolutions. Each point is the time per query (log scale; ' +
      'for the mesh route it includes polygonizing and building every mesh that changed in that ' +
      'frame) against the share of wrong answers (missed overlaps and false contacts; frames the ' +
      'octree calls touching within its precision are not counted). Beside each chart, the ' +
      'preview (the witness of the first collision as a red dot) and the octree\'s verdicts.');
    const comparisons = data.frep || [];
    if (comparisons.length === 0) empty(s, 'No FRep comparison in this study (collido study ' +
      '... --frep FILE, or collido report DIR --frep F).');
    const frepBackends = ['frep:octree', ...new Set(comparisons.flatMap(
      (c) => c.comparators.map((b) => b.backend)))].sort();
    for (const c of comparisons) {
      const name = c.name || c.file;
      const box = el('div', { class: 'charts' });
      s.appendChild(box);
      const seedMs = (c.seed || []).map((r) => r.median_ms).sort((a, b) => a - b);
      const median = seedMs.length ? seedMs[Math.floor((seedMs.length - 1) / 2)] : null;
      const values = c.comparators.filter((b) => b.status === 'ok').map((b) => {
        const decided = b.agrees + b.missed + b.false_contacts;
        return { backend: b.backend, label: b.backend + ' @' + b.resolution,
          resolution: b.resolution, ms: Math.max(b.ms_per_query_with_meshing, 1e-4),
          wrong_rate: decided > 0 ? b.wrong / decided : 0, missed: b.missed,
          false_contacts: b.false_contacts, triangles: b.triangles_first_pair };
      });
      if (median !== null) {
        values.push({ backend: 'frep:octree', label: 'frep:octree (ε ' + c.precision + ')',
          resolution: null, ms: Math.max(median, 1e-4), wrong_rate: 0, missed: 0,
          false_contacts: 0, triangles: null });
      }
      chart(box, 'frep:' + name, {
        title: name, width: 420, height: 240, data: { values: values },
        mark: { type: 'point', filled: true, size: 80 },
        encoding: {
          x: { field: 'ms', type: 'quantitative', scale: { type: 'log' },
            title: 'time per query, ms (mesh route: with polygonization)' },
          y: { field: 'wrong_rate', type: 'quantitative', title: 'share of wrong answers',
            scale: { domain: [0, 1] } },
          color: { field: 'backend', type: 'nominal', title: 'backend',
            scale: { domain: frepBackends } },
          tooltip: [{ field: 'label', title: 'backend' }, { field: 'ms', format: '.3f' },
            { field: 'wrong_rate', format: '.2f' }, { field: 'missed' },
            { field: 'false_contacts', title: 'false contacts' }, { field: 'triangles' }] } });
      if (c.preview_png) {
        box.appendChild(el('img', { class: 'preview', src: c.preview_png,
          alt: 'ray-cast preview of ' + name, 'data-view': 'frep-preview:' + name }));
      }
      const verdicts = {};
      for (const r of c.seed || []) verdicts[r.verdict] = (verdicts[r.verdict] || 0) + 1;
      const cells = Math.max(0, ...(c.seed || []).map((r) => r.cells));
      table(s, ['pair queries', 'verdicts', 'octree median ms', 'max ms', 'max cells', 'precision'],
        [[String((c.seed || []).length),
          Object.entries(verdicts).map(([k, v]) => v + ' ' + k).join(', '),
          fmt(median, 3), fmt(seedMs.length ? seedMs[seedMs.length - 1] : null, 3), String(cells),
          String(c.precision)]]);
      const failed = c.comparators.filter((b) => b.status !== 'ok');
      const problems = (c.problems || []).map((p) => el('li', { text: p }));
      if (failed.length + problems.length > 0) {
        s.appendChild(el('ul', {}, problems.concat(failed.map((b) => el('li', { text: b.backend +
          ' @' + b.resolution + ': ' + b.status })))));
      }
    }
  }

  // --- robustness matrix ----------------------------------------------------------------------
  {
    const s = section('robustness', 'Robustness matrix',
      'Every backend setting on the stress scenes (scenes/stress/), by robustness category: the ' +
      'share of cases whose answer differs from the exact oracle\'s, for the boolean question ' +
      'and for the set of intersecting triangle pairs. Green is none wrong; grey is a question the ' +
      'backend does not answer (unsupported), brown one it failed to answer (errors, crashed ' +
      'workers): neither is ever shown as zero errors. The tooltip has the counts: false ' +
      'negatives and positives, missed and extra triangle pairs.');
    const cells = data.robustness || [];
    if (cells.length === 0) {
      empty(s, 'No stress scene in this study: add scenes/stress/*.json (tools/study.sh does) ' +
        'to measure each backend at the edges.');
    } else {
      const pct = (x) => (x === null || x === undefined) ? '-' : fmt(100 * x, 1) + '%';
      const values = (kind) => cells.map((c) => {
        const a = kind === 'boolean' ? c.boolean : kind === 'distance' ? c.distance : c.all_pairs;
        const measured = a.status === 'measured';
        return {
          backend: c.backend, category: c.category, cases: c.cases, status: a.status,
          rate: measured ? a.wrong_rate : null,
          text: measured ? (a.wrong === 0 ? '0' : pct(a.wrong_rate)) : a.status,
          wrong: a.wrong, answered: a.answered, false_negatives: a.false_negatives,
          false_positives: a.false_positives, unsupported: a.unsupported, failed: a.failed,
          invalid_pairs: a.invalid_pairs,
          true_pairs: a.true_pairs === undefined ? null : a.true_pairs,
          missed: a.missed_pairs === undefined ? null : a.missed_pairs + ' (' + pct(a.missed_share) + ')',
          extra: a.extra_pairs === undefined ? null : a.extra_pairs + ' (' + pct(a.extra_share) + ')',
          workers: c.worker_failures.join('; ') || null };
      });
      const categories = [...new Set(cells.map((c) => c.category))];
      const settings = [...new Set(cells.map((c) => c.backend))];
      const box = el('div', { class: 'charts' });
      s.appendChild(box);
      const kinds = [['boolean', 'Wrong boolean answers'], ['all_pairs', 'Wrong all-pairs answers']];
      // The distance category's answers, held to the exact distance at contact scale.
      if (cells.some((c) => c.distance && c.distance.status !== 'none')) {
        kinds.push(['distance', 'Wrong distance answers (0 for apart, positive for touching, ' +
          'or off by more than 1e-6 of the exact distance)']);
      }
      for (const [kind, title] of kinds) {
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
        const x = { field: 'category', type: 'nominal', sort: categories, title: null,
          axis: { labelAngle: -30 } };
        const y = { field: 'backend', type: 'nominal', sort: settings, title: null,
          axis: { labelLimit: 420 } };
        chart(box, 'robustness:' + kind, {
          title: title, data: { values: values(kind) },
          width: { step: 78 }, height: { step: 20 },
          encoding: { x: x, y: y, tooltip: tooltip },
          layer: [
            { transform: [{ filter: 'datum.rate !== null' }], mark: { type: 'rect', stroke: '#fff' },
              encoding: { color: {
                condition: { test: 'datum.rate === 0', value: '#cfead4' },
                field: 'rate', type: 'quantitative', title: 'share wrong',
                scale: { type: 'sqrt', domain: [0, 1], scheme: 'orangered' } } } },
            { transform: [{ filter: 'datum.rate === null' }], mark: { type: 'rect', stroke: '#fff' },
              encoding: { color: {
                condition: { test: "datum.status === 'unsupported'", value: '#d4d4d4' },
                value: '#a5806a' } } },
            { mark: { type: 'text', fontSize: 9 },
              encoding: { text: { field: 'text' },
                color: { condition: { test: 'datum.rate > 0.3', value: '#fff' }, value: '#222' } } }] });
      }
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
  }

  // --- 2. time distributions ------------------------------------------------------------------
  {
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

  // --- 2b. deforming scenes: update and query per frame ----------------------------------------
  {
    const s = section('deforming', 'Deforming scenes over time',
      'Per frame of each deforming scene: the cost of giving every deforming object its new ' +
      'positions (update: a refit, a rebuild or a state switch) and of the query after it, per ' +
      'backend setting (log scale). Frames whose answer differed from the oracle\'s are ringed: ' +
      'an answer from stale boxes shows there.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const groups = groupBy(data.deforming || [], (d) => d.scene + ' · ' + d.query);
    if (groups.size === 0) empty(s, 'No deforming scene in this study (scenes with states or ' +
      '"deform": scenes/README.md).');
    for (const [name, frames] of groups) {
      const values = frames.map(tagByLookup);
      const rows = [];
      for (const v of values) {
        rows.push(Object.assign({}, v, { part: 'update', us: Math.max(v.update_us, 1e-3) }));
        rows.push(Object.assign({}, v, { part: 'update + query',
          us: Math.max(v.update_us + v.query_us, 1e-3) }));
      }
      const layers = [
        { mark: { type: 'line', point: false },
          encoding: { x: { field: 'frame', type: 'quantitative', title: 'frame' },
            y: { field: 'us', type: 'quantitative', scale: { type: 'log' }, title: 'µs' },
            color: familyColourOf(values), detail: { field: 'label' },
            strokeDash: { field: 'part', type: 'nominal', title: 'cost' },
            tooltip: [{ field: 'label', title: 'backend' }, { field: 'frame' },
              { field: 'update_us', title: 'update µs', format: '.1f' },
              { field: 'rebuilds', title: 'rebuilds' },
              { field: 'query_us', title: 'query µs', format: '.1f' },
              { field: 'wrong', title: 'wrong answer' }] } }];
      // Rings on the frames answered wrongly; drawn on every point, seen only on those (a layer
      // the filters could empty would have no extent).
      if (values.some((v) => v.wrong)) {
        layers.push({ mark: { type: 'point', shape: 'circle', size: 60, filled: false },
          encoding: { x: { field: 'frame', type: 'quantitative' },
            y: { field: 'us', type: 'quantitative', scale: { type: 'log' } },
            color: familyColour, detail: { field: 'label' },
            opacity: { condition: { test: 'datum.wrong && datum.part === "update + query"',
              value: 1 }, value: 0 } } });
      }
      filteredChart(box, 'deforming:' + name, {
        title: name, width: 420, height: 220, data: { values: rows }, layer: layers }, rows);
    }
  }

  // --- 2c. tracked markers: contact at the true and at the recovered poses --------------------
  {
    const s = section('tracking', 'Poses from tracked markers',
      'Per frame of each scene whose objects are posed from tracked markers: whether the exact ' +
      'answer says contact at the true poses and at the poses recovered from the markers (which ' +
      'every backend is given). Frames where they differ are ringed: a false or a missed ' +
      'contact caused by tracking error, whatever the backend.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const groups = groupBy(data.tracking || [], (d) => d.scene + ' · ' + d.query);
    if (groups.size === 0) empty(s, 'No scene with tracked markers in this study ("markers": ' +
      'scenes/README.md).');
    for (const [name, values] of groups) {
      const rows = [];
      for (const v of values) {
        rows.push({ frame: v.frame, poses: 'true', contact: v.truth ? 1 : 0,
          differs: v.truth !== v.recovered });
        rows.push({ frame: v.frame, poses: 'recovered', contact: v.recovered ? 1 : 0,
          differs: v.truth !== v.recovered });
      }
      const layers = [
        { mark: { type: 'line', interpolate: 'step-after', point: true },
          encoding: { x: { field: 'frame', type: 'quantitative', title: 'frame' },
            y: { field: 'contact', type: 'quantitative', title: 'contact',
              scale: { domain: [-0.1, 1.1] }, axis: { values: [0, 1] } },
            color: { field: 'poses', type: 'nominal', title: 'poses' },
            tooltip: [{ field: 'frame' }, { field: 'poses' }, { field: 'contact' }] } }];
      if (values.some((v) => v.truth !== v.recovered)) {
        layers.push({ transform: [{ filter: 'datum.differs && datum.poses === "recovered"' }],
          mark: { type: 'point', shape: 'circle', size: 140, filled: false, color: '#c0392b' },
          encoding: { x: { field: 'frame', type: 'quantitative' },
            y: { field: 'contact', type: 'quantitative' } } });
      }
      chart(box, 'tracking:' + name, {
        title: name, width: 420, height: 140, data: { values: rows }, layer: layers });
    }
  }

  // --- 2d. pose error from tracked markers (collido pose-error sweeps) ------------------------
  {
    const s = section('pose-error', 'Pose error from tracked markers',
      'From collido pose-error sweeps (collido report --pose-error FILE): the worst displacement ' +
      'of the object\'s mesh by the fitted pose (median over seeded random true poses) against ' +
      'the marker count, per solver, noise and dropout rate, one chart per marker layout (log ' +
      'scale). Rows whose fits were all refused (too few markers, one plane for the affine fit) ' +
      'have no point; the tooltip gives the refusals.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const sweeps = data.pose_error || [];
    if (sweeps.length === 0) empty(s, 'No pose-error sweep given (collido pose-error SCENE ' +
      '--object NAME --json F, then collido report DIR --pose-error F).');
    for (const sweep of sweeps) {
      const groups = groupBy(sweep.rows, (r) => r.layout);
      for (const [layout, rows] of groups) {
        const values = rows.filter((r) => r.worst_vertex_median !== null).map((r) => Object.assign(
          {}, r, { series: r.solver + ', noise ' + r.noise + ', dropout ' + r.dropout }));
        if (values.length === 0) continue;
        const name = sweep.scene + ' · ' + sweep.object + ' · ' + layout;
        chart(box, 'pose-error:' + name, {
          title: name, width: 420, height: 220, data: { values: values },
          mark: { type: 'line', point: true },
          encoding: { x: { field: 'markers', type: 'quantitative', title: 'markers' },
            y: { field: 'worst_vertex_median', type: 'quantitative', scale: { type: 'log' },
              title: 'worst vertex displacement (median)' },
            color: { field: 'series', type: 'nominal', title: 'solver, noise, dropout' },
            tooltip: [{ field: 'solver' }, { field: 'markers' }, { field: 'noise' },
              { field: 'dropout' }, { field: 'worst_vertex_median', format: '.2e' },
              { field: 'worst_vertex_p90', format: '.2e' },
              { field: 'rotation_deg_median', title: 'rotation deg', format: '.3f' },
              { field: 'failed', title: 'refused' }, { field: 'trials' },
              { field: 'solve_us_median', title: 'solve µs', format: '.1f' }] } });
      }
    }
  }

  // --- 3. memory per triangle -----------------------------------------------------------------
  {
    const s = section('memory', 'Memory per triangle',
      'Bytes per triangle of the built structures of both objects: what the backend says, and ' +
      'what its build kept on the heap, counted by allocation hooks in the worker ' +
      '(independent of the backend). The tooltip adds the build peak and the resident memory ' +
      'the backend added at its peak, apart from the scene and the exact answers the worker held.');
    const rows = [];
    for (const [, queries] of groupBy(charted, (r) => r.label + '|' + r.scene)) {
      const r = queries[0];
      const bar = (measure, bytes) => tagged({ label: r.label, scene: r.scene, measure: measure,
        bytes: bytes, rss_mib: r.backend_rss_mib, heap_peak: r.heap_peak_bytes_per_triangle },
      family(r.backend), queries);
      rows.push(bar('backend figure', r.bytes_per_triangle));
      if (r.heap_bytes_per_triangle !== null) rows.push(bar('heap kept (hooks)', r.heap_bytes_per_triangle));
    }
    if (rows.length === 0) {
      empty(s, 'No built structure.');
    } else {
      const box = el('div', { class: 'charts' });
      s.appendChild(box);
      // One chart per scene, listing only the settings run on it.
      for (const [scene, bars] of groupBy(rows, (r) => r.scene)) {
        filteredChart(box, 'memory:' + scene, {
          title: scene, data: { values: bars }, width: 300, height: { step: 10 }, mark: 'bar',
          encoding: { y: { field: 'label', type: 'nominal', title: null, axis: { labelLimit: 220 } },
            yOffset: { field: 'measure' },
            x: { field: 'bytes', type: 'quantitative', title: 'bytes per triangle' },
            color: familyColourOf(bars),
            opacity: { field: 'measure', type: 'ordinal', title: null, scale: { range: [1, 0.45] } },
            tooltip: [{ field: 'label' }, { field: 'measure' }, { field: 'bytes', format: '.0f' },
              { field: 'heap_peak', title: 'build peak B/tri', format: '.0f' },
              { field: 'rss_mib', title: 'backend peak RSS (MiB)', format: '.0f' }] } }, bars);
      }
    }
  }

  // --- 4. scaling -----------------------------------------------------------------------------
  {
    const s = section('scaling', 'Scaling',
      'Time per query (the mean over frames of each frame\'s median call, whiskers its 95% ' +
      'interval) and memory against the number of triangles (log-log), for scenes ' +
      'run at several resolutions. The table gives the fitted exponent k of time ~ n^k.');
    const families = groupBy(charted, (r) => r.scene + ' · ' + r.query);
    const curves = [];
    const exponents = [];
    for (const [name, rows] of families) {
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
    } else {
      const box = el('div', { class: 'charts' });
      s.appendChild(box);
      for (const [name, rows] of groupBy(curves, (r) => r.group)) {
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
      table(s, ['scene · query', 'backend', 'sizes', 'time exponent', 'B/tri exponent'], exponents,
        ['', '', 'num', 'num', 'num']);
    }
  }

  // --- 5. failures ----------------------------------------------------------------------------
  {
    const s = section('failures', 'Failures, wrong answers and gaps',
      'Three lists: what failed in the run (crashes, timeouts and failed workers, which the study ' +
      'went on without, and queries that failed or whose input was refused), queries with ' +
      'answers that differ from the exact oracle, and the queries some backend does not answer ' +
      'by design, each listed once per backend setting; then the settings not planned on a ' +
      'scene at all, since they answer none of the kinds it asks.');
    const part = (id, title) => {
      const holder = el('div', { id: id, class: 'part' }, [el('h3', { text: title })]);
      s.appendChild(holder);
      return holder;
    };
    const failureTable = (holder, list) => laterTable(holder,
      ['what', 'backend / setting', 'scene', 'query', 'detail'], list.map((f) => {
        const detail = el('div', { text: f.detail });
        if (f.log) detail.appendChild(el('pre', { class: 'log', text: f.log }));
        return [f.what, f.label, f.scene, f.query, detail];
      }), ['bad']);
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

  // --- 5b. scene views ------------------------------------------------------------------------
  {
    const s = section('scene-views', 'Scenes in 3D',
      'Each scene\'s 3D view (collido view): the meshes frame by frame and, for each backend ' +
      'the study ran on it, the triangles it reports as intersecting, the exact oracle\'s, and ' +
      'the pairs it missed or added.');
    const views = data.views || [];
    if (views.length === 0) {
      empty(s, 'No views beside this study (tools/study.sh writes them into views/).');
    } else {
      const list = el('ul', { class: 'view-links' });
      for (const v of views) {
        const item = el('li');
        item.appendChild(el('a', { href: v.href, text: v.scene, 'data-scene': v.scene }));
        list.appendChild(item);
      }
      s.appendChild(list);
    }
  }

  // --- 6. needs -------------------------------------------------------------------------------
  {
    const s = section('needs', 'What the scene\'s needs save',
      'Scenes run three ways: every (each object built for every query kind the backend answers, ' +
      'every pair asked in every frame: the cold figure), declared (built for the scene\'s queries ' +
      'only) and changed (built as declared; a pair neither of whose objects moved, changed state or ' +
      'deformed since the frame before takes that answer instead of being asked, and a two-object ' +
      'collision query whose pair the shared broad phase proves apart is not asked; both answers ' +
      'are still checked against the exact reference). Query times are the mean over frames of ' +
      'each frame\'s median call, with its 95% interval in the table.');
    const key = (r) => r.backend + '|' + r.scene + '|' + r.resolution + '|' + r.limit + '|' + r.query;
    const byMode = (mode) => new Map(ok.filter((r) => r.needs === mode).map((r) => [key(r), r]));
    const declared = byMode('declared');
    const changed = byMode('changed');
    const bars = [];
    const rows = [];
    const pct = (every, now) => (every > 0 ? ` (${Math.round(100 * (every - now) / every)}%)` : '');
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
      // As table.txt's needs table: the time with its 95% interval.
      const time = (r) => (r ? withInterval(timeOf(r), ciOf(r)) : '-');
      rows.push([e.backend, e.scene, e.query,
        `${Math.round(e.bytes_per_triangle)} → ${Math.round(built.bytes_per_triangle)}` +
          pct(e.bytes_per_triangle, built.bytes_per_triangle),
        `${fmt(e.build_ms)} → ${fmt(built.build_ms)}` + pct(e.build_ms, built.build_ms),
        time(e), time(d), time(h),
        h ? `${h.unasked_frames || 0} of ${h.frames}` : '-',
        h ? `${h.reused_pairs || 0} / ${h.skipped_pairs || 0}` : '-',
        h ? String(h.disagreements) : '-']);
    }
    if (rows.length === 0) {
      empty(s, 'The study ran no scene both with needs "every" and "declared" or "changed": ' +
        'add them to the sweep\'s "needs" (docs/STUDY.md).');
    } else {
      laterTable(s, ['backend / setting', 'scene', 'query', 'B/tri every → declared', 'build ms every → declared',
        'mean µs every', 'declared', 'changed', 'frames unasked', 'pairs reused / culled',
        'wrong (changed)'], rows);
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
  }

  // --- 7. before / after ----------------------------------------------------------------------
  {
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
    } else {
      const counts = changes.counts;
      s.appendChild(el('p', { class: 'baseline-counts', text: `${changes.rows.length} rows: ` +
        `${counts.faster} faster, ${counts.slower} slower, ${counts.same} the same.` }));
      const labelOf = (r) => (r.setting ? r.backend + ' ' + r.setting : r.backend);
      const ratios = changes.rows.filter((r) => typeof r.ratio === 'number').map((r) => ({
        label: labelOf(r), scene: r.scene, query: r.query, ratio: r.ratio,
        lo: r.ratio_ci95[0], hi: r.ratio_ci95[1], change: r.change,
        interval: `[${fmt(r.ratio_ci95[0], 2)}, ${fmt(r.ratio_ci95[1], 2)}]`,
        before: withInterval(r.before_us, r.before_ci95_us), now: withInterval(r.now_us, r.now_ci95_us) }));
      const before = new Map((data.baseline_rows || []).filter((r) => r.status === 'ok')
        .map((r) => [r.key, r]));
      const errors = [];
      for (const r of ok) {
        const b = before.get(r.key);
        if (b && b.disagreements !== r.disagreements) {
          errors.push([r.label, r.scene, r.query, String(b.disagreements), String(r.disagreements)]);
        }
      }
      const box = el('div', { class: 'charts' });
      s.appendChild(box);
      const x = { type: 'quantitative', scale: { type: 'log' }, title: 'now / before (mean time), 95% CI' };
      const colour = { field: 'change', type: 'nominal', title: 'change',
        scale: { domain: ['faster', 'same', 'slower'], range: ['#1b7f3b', '#9a9a9a', '#b3261e'] } };
      // One chart a scene, each listing only the settings that ran on it.
      for (const [scene, rows] of groupBy(ratios, (r) => r.scene)) {
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
      if (errors.length) {
        table(s, ['backend / setting', 'scene', 'query', 'wrong frames before', 'now'], errors,
          ['', '', '', 'num', 'num']);
      }
    }
  }

  // --- the table ------------------------------------------------------------------------------
  // table.txt's columns, declared once in the runner (measurement_columns.h), cells and all.
  {
    const s = section('table', 'All measurements', 'Every (backend setting, scene, query), as ' +
      'table.txt shows it. ' + data.columns_legend);
    laterTable(s, ['backend / setting', 'scene', 'query', 'status', ...data.columns],
      data.rows.map((r) => [r.label, r.scene, r.query, r.status,
        ...(r.cells.length ? r.cells : data.columns.map(() => '-'))]),
      ['', '', '', '', ...data.columns.map(() => 'num')]);
  }

  applyFilters();
  // The observer reports what is in view at the next frame; ready once those charts are drawn.
  window.COLLIDO_REPORT.ready = new Promise((resolve) => requestAnimationFrame(() =>
    setTimeout(resolve, 0))).then(() => Promise.all(drawing)).then(() => {
    document.body.setAttribute('data-ready', 'true');
  });
})();
