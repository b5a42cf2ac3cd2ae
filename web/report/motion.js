// Scenes that move beyond rigid poses: the cost per frame of deforming scenes, contact at the true
// and at the tracked poses, and the pose error of marker fits (collido pose-error sweeps).
const ReportMotion = (() => {
  'use strict';
  const { el, section, empty } = ReportDom;
  const { chart, filteredChart } = ReportCharts;
  const { groupBy } = ReportModel;

  // --- deforming scenes: update and query per frame -------------------------------------------
  function deformingChart(box, name, frames, model) {
    const { tagByLookup, familyColour, familyColourOf } = model;
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

  function deforming(model) {
    const s = section('deforming', 'Deforming scenes over time',
      'Per frame of each deforming scene: the cost of giving every deforming object its new ' +
      'positions (update: a refit, a rebuild or a state switch) and of the query after it, per ' +
      'backend setting (log scale). Frames whose answer differed from the oracle\'s are ringed: ' +
      'an answer from stale boxes shows there.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const groups = groupBy(model.data.deforming || [], (d) => d.scene + ' · ' + d.query);
    if (groups.size === 0) empty(s, 'No deforming scene in this study (scenes with states or ' +
      '"deform": scenes/README.md).');
    for (const [name, frames] of groups) deformingChart(box, name, frames, model);
  }

  // --- tracked markers: contact at the true and at the recovered poses ------------------------
  function trackingChart(box, name, values) {
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

  function tracking(model) {
    const s = section('tracking', 'Poses from tracked markers',
      'Per frame of each scene whose objects are posed from tracked markers: whether the exact ' +
      'answer says contact at the true poses and at the poses recovered from the markers (which ' +
      'every backend is given). Frames where they differ are ringed: a false or a missed ' +
      'contact caused by tracking error, whatever the backend.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const groups = groupBy(model.data.tracking || [], (d) => d.scene + ' · ' + d.query);
    if (groups.size === 0) empty(s, 'No scene with tracked markers in this study ("markers": ' +
      'scenes/README.md).');
    for (const [name, values] of groups) trackingChart(box, name, values);
  }

  // --- pose error from tracked markers (collido pose-error sweeps) ----------------------------
  function poseErrorChart(box, name, values) {
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

  function poseError(model) {
    const s = section('pose-error', 'Pose error from tracked markers',
      'From collido pose-error sweeps (collido report --pose-error FILE): the worst displacement ' +
      'of the object\'s mesh by the fitted pose (median over seeded random true poses) against ' +
      'the marker count, per solver, noise and dropout rate, one chart per marker layout (log ' +
      'scale). Rows whose fits were all refused (too few markers, one plane for the affine fit) ' +
      'have no point; the tooltip gives the refusals.');
    const box = el('div', { class: 'charts' });
    s.appendChild(box);
    const sweeps = model.data.pose_error || [];
    if (sweeps.length === 0) empty(s, 'No pose-error sweep given (collido pose-error SCENE ' +
      '--object NAME --json F, then collido report DIR --pose-error F).');
    for (const sweep of sweeps) {
      const groups = groupBy(sweep.rows, (r) => r.layout);
      for (const [layout, rows] of groups) {
        const values = rows.filter((r) => r.worst_vertex_median !== null).map((r) => Object.assign(
          {}, r, { series: r.solver + ', noise ' + r.noise + ', dropout ' + r.dropout }));
        if (values.length === 0) continue;
        poseErrorChart(box, sweep.scene + ' · ' + sweep.object + ' · ' + layout, values);
      }
    }
  }

  return { deforming, tracking, poseError };
})();
