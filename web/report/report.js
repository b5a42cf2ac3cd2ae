// Collidoscope's dashboard (`collido report`): reads the study data inlined in the page and
// composes the page, with Vega-Lite, from the modules listed before this file in scripts.json.
(() => {
  'use strict';
  const data = JSON.parse(document.getElementById('collido-data').textContent);
  // A chart is drawn when it comes near the window (a full study has hundreds);
  // COLLIDO_REPORT.renderAll() draws every one. Each chart container gets data-rendered="true"
  // once drawn (or data-error with the reason), which the browser test checks; the body gets
  // data-ready="true" once the charts in view are drawn.
  window.COLLIDO_REPORT = { ready: null, errors: ReportCharts.errors,
    renderAll: ReportDom.renderAll };
  const model = ReportModel.build(data);

  ReportHeader.summary(model);
  ReportHeader.filterBar(model);
  // The sections in the page's order.
  ReportPick.render(model);
  ReportTimeError.timeVsError(model);
  ReportTimeError.distanceError(model);
  ReportTimeError.contactError(model);
  ReportTimeError.betweenFrames(model);
  ReportSurfaces.surfaces(model);
  ReportSurfaces.frep(model);
  ReportRobustness.render(model);
  ReportDistributions.render(model);
  ReportMotion.deforming(model);
  ReportMotion.tracking(model);
  ReportMotion.poseError(model);
  ReportMemory.render(model);
  ReportScaling.render(model);
  ReportFailures.render(model);
  ReportSceneViews.render(model);
  ReportNeeds.render(model);
  ReportBaseline.render(model);
  ReportMeasurements.render(model);

  ReportCharts.applyFilters();
  // The observer reports what is in view at the next frame; ready once those charts are drawn.
  window.COLLIDO_REPORT.ready = new Promise((resolve) => requestAnimationFrame(() =>
    setTimeout(resolve, 0))).then(() => ReportDom.drawn()).then(() => {
    document.body.setAttribute('data-ready', 'true');
  });
})();
