// All measurements: every (backend setting, scene, query) with table.txt's columns, which the
// runner declares once (measurement_columns.h), cells and all.
const ReportMeasurements = (() => {
  'use strict';
  const { section, laterTable } = ReportDom;

  function render(model) {
    const { data } = model;
    const s = section('table', 'All measurements', 'Every (backend setting, scene, query), as ' +
      'table.txt shows it. ' + data.columns_legend);
    laterTable(s, ['backend / setting', 'scene', 'query', 'status', ...data.columns],
      data.rows.map((r) => [r.label, r.scene, r.query, r.status,
        ...(r.cells.length ? r.cells : data.columns.map(() => '-'))]),
      ['', '', '', '', ...data.columns.map(() => 'num')]);
  }

  return { render };
})();
