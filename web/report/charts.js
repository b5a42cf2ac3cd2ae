// Vega-Lite charts, drawn when they come near the window with their log axes tidied, and the
// chart filters' state: the backend family, query kind and "exact only" the filtered charts show.
const ReportCharts = (() => {
  'use strict';
  const { el, later } = ReportDom;
  // Every chart that failed, "name: reason" (the page's COLLIDO_REPORT.errors).
  const errors = [];
  const filterState = { family: 'all', query: 'all', exact: false };
  const filterParamOf = { family_pick: 'family', query_pick: 'query', exact_only: 'exact' };

  // A chart container gets data-rendered="true" once drawn (or data-error with the reason),
  // which the browser test checks.
  function chart(parent, name, spec, onView) {
    const holder = el('div', { class: 'chart', 'data-view': name });
    parent.appendChild(holder);
    spec.$schema = 'https://vega.github.io/schema/vega-lite/v6.json';
    // Labels that would touch are dropped (with no gap, "2,000" and "3,000" read "2,0003,000").
    spec.config = Object.assign({ font: 'system-ui, sans-serif',
      axis: { labelFontSize: 11, labelOverlap: 'greedy', labelSeparation: 6 } }, spec.config || {});
    tidyLogAxes(spec);
    holder.classList.add('waiting');
    later(holder, () => {
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
          errors.push(name + ': ' + e);
          console.error('chart ' + name + ' failed: ' + e);
        });
    });
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

  // --- chart filters --------------------------------------------------------------------------
  // What the filters read from a chart's datum (model.js tags it): its family, the query kinds
  // it covers (",boolean,distance,") and whether it is exact on every frame.
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
  // The filters as the controls now say ({ family, query, exact }), applied to every chart.
  function setFilters(state) {
    Object.assign(filterState, state);
    applyFilters();
  }

  return { chart, filteredChart, applyFilters, setFilters, errors };
})();
