// Run time against error: every setting's time against its share of wrong frames (with the
// Pareto front), against its distance error, and against its contact error.
const ReportTimeError = (() => {
  'use strict';
  const { timeOf, ciOf, withInterval, TIME_TITLE } = ReportFormat;
  const { el, section, laterTable, empty } = ReportDom;
  const { filteredChart } = ReportCharts;
  const { groupBy } = ReportModel;

  // --- time against the share of wrong frames -------------------------------------------------
  function paretoChart(box, name, points, model) {
    const { familyColourOf, settingShape } = model;
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

  function timeVsError(model) {
    const s = section('time-vs-error', 'Run time against error',
      'One point per backend setting: its time per query (log scale), the mean over frames of ' +
      'each frame\'s median call, whiskers its 95% interval, against the share of ' +
      'frames whose answer differs from the exact oracle. Colour is the backend family, shape ' +
      'the setting within it (named in the tooltip). The dashed line joins the Pareto front, ' +
      'the settings no other one beats on both, each named beside its point; it follows the ' +
      'filters above. Points at 0% are exact on every frame of the scene.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const groups = groupBy(model.charted, (r) => r.scene + ' · ' + r.query);
    if (groups.size === 0) empty(s, 'No measured query.');
    for (const [name, rows] of groups) paretoChart(box, name, rows.map(model.tagRow), model);
  }

  // --- time against a measured error ----------------------------------------------------------
  // The time (log, whiskers its 95% interval) against an error on a symlog scale: linear below
  // 1e-16, logarithmic above, so an answer exact to the last bit sits on the 0 line instead of
  // at an invented floor. The chart the distance and contact sections share.
  function timeAgainstErrorChart(box, name, points, error, title, tooltip, model) {
    const { tagRow, familyColourOf, settingShape } = model;
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

  // --- distances ------------------------------------------------------------------------------
  function distanceError(model) {
    const s = section('distance-error', 'Distances: run time against error',
      'Distance queries only: time per query (log scale; the mean over frames of each frame\'s ' +
      'median call, whiskers its 95% interval) against the largest error of ' +
      'the reported distance over the frames, relative to the exact distance (symlog scale: ' +
      'linear below 1e-16, so an answer exact to the last bit is drawn at 0). The share of wrong frames (time against ' +
      'error above) also counts closest points that do not hold together.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const rows = model.charted.filter((r) => r.kind === 'distance' &&
      r.max_distance_error !== null && r.max_distance_error !== undefined);
    const groups = groupBy(rows, (r) => r.scene + ' · ' + r.query);
    if (groups.size === 0) empty(s, 'No measured distance query.');
    for (const [name, points] of groups) {
      timeAgainstErrorChart(box, 'distance-error:' + name, points,
        (p) => (p.max_relative_distance_error === null ? p.max_distance_error :
          p.max_relative_distance_error), 'largest relative distance error',
        [{ field: 'max_distance_error', format: '.3g' },
          { field: 'max_relative_distance_error', format: '.3g' },
          { field: 'error_rate', format: '.3f' }], model);
    }
  }

  // --- contacts -------------------------------------------------------------------------------
  const figure = (v, digits) => (v === null || v === undefined ? '-' : v.toPrecision(digits));
  // One line of the contacts table: every contact figure of a setting.
  const contactLine = (name, p) => [name, p.label, withInterval(timeOf(p), ciOf(p)),
    figure(p.contacts_per_frame, 3), figure(p.contact_position_error, 3),
    figure(p.contact_surface_error, 3), figure(p.contact_normal_error_deg, 3),
    figure(p.contact_depth_error, 3),
    typeof p.contact_coverage !== 'number' ? '-' : (100 * p.contact_coverage).toFixed(1) + '%',
    String(p.contact_false_pairs)];

  function contactError(model) {
    const s = section('contact-error', 'Contacts: run time against contact error',
      'Contacts queries only, each contact held to the exact contact of its triangle pair ' +
      '(docs/DESIGN.md, "Contact geometry"): time per query (log scale; the mean over frames of ' +
      'each frame\'s median call, whiskers its 95% interval) against the ' +
      'largest distance of a contact point to its pair\'s exact intersection set (symlog ' +
      'scale: linear below 1e-16, so an exact point is drawn at 0). The table gives every contact figure.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const rows = model.charted.filter((r) => r.kind === 'contacts' &&
      r.contacts_per_frame !== null && r.contacts_per_frame !== undefined);
    const groups = groupBy(rows, (r) => r.scene + ' · ' + r.query);
    if (groups.size === 0) empty(s, 'No measured contacts query.');
    const lines = [];
    for (const [name, points] of groups) {
      timeAgainstErrorChart(box, 'contact-error:' + name, points,
        (p) => p.contact_position_error, 'largest contact point error',
        [{ field: 'contacts_per_frame', format: '.1f' },
          { field: 'contact_position_error', format: '.3g' },
          { field: 'contact_normal_error_deg', format: '.3g' },
          { field: 'contact_depth_error', format: '.3g' },
          { field: 'contact_coverage', format: '.3f' },
          { field: 'contact_false_pairs' }], model);
      for (const p of points) lines.push(contactLine(name, p));
    }
    if (lines.length > 0) {
      laterTable(s, ['scene · query', 'backend / setting', 'mean µs [95% CI]', 'contacts/frame', 'point err',
        'surface err', 'normal °', 'depth err', 'coverage', 'false pairs'], lines);
    }
  }

  // --- between the frames ---------------------------------------------------------------------
  const count = (v) => (v === null || v === undefined ? '-' : String(v));
  function betweenFrames(model) {
    const s = section('between-frames', 'Between the frames: first contact over a step',
      'Queries asked over a step, frame k to k + 1 (docs/ORACLE.md, "First contact over a ' +
      'step"): time per step (log scale; the mean over steps of each step\'s median call, ' +
      'whiskers its 95% interval) against the largest error of the first-contact time, as a ' +
      'share of the step (symlog scale: an answer within rounding of the oracle\'s bracket is ' +
      'drawn at 0), one chart for each query where some step touches. A backend\'s own answer ' +
      'is certified; substeps=N is the runner\'s discrete checks at N + 1 times of the step, ' +
      'whose error is up to 1/N and which miss a contact no check lands on. The table counts, ' +
      'for every query, the touching steps each setting missed or made up, and those coarser ' +
      'than asked; table.txt ("Between the frames") names what to pick.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const rows = model.charted.filter((r) => r.kind === 'first_contact');
    const groups = groupBy(rows, (r) => r.scene + ' · ' + r.query);
    if (groups.size === 0) empty(s, 'No measured first-contact query.');
    const lines = [];
    for (const [name, points] of groups) {
      if (points.some((p) => p.max_first_contact_error !== null &&
        p.max_first_contact_error !== undefined)) {
        timeAgainstErrorChart(box, 'first-contact-error:' + name, points,
          (p) => p.max_first_contact_error, 'largest first-contact time error',
          [{ field: 'false_negatives', title: 'missed steps' },
            { field: 'false_positives', title: 'false steps' },
            { field: 'coarse_steps', title: 'coarser than asked' },
            { field: 'max_first_contact_error', format: '.3g' }], model);
      }
      for (const p of points) {
        lines.push([name, p.label, withInterval(timeOf(p), ciOf(p)), count(p.frames),
          count(p.false_negatives), count(p.false_positives), figure(p.max_first_contact_error, 3),
          count(p.coarse_steps), count(p.disagreements)]);
      }
    }
    if (lines.length > 0) {
      laterTable(s, ['scene · query', 'backend / setting', 'mean µs a step [95% CI]', 'steps',
        'missed', 'false', 'time err', 'coarse', 'wrong steps'], lines);
    }
  }

  return { timeVsError, distanceError, contactError, betweenFrames };
})();
