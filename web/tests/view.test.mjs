// Opens a view made by `collido view` in headless Chromium (software WebGL) and checks it
// against the answers `collido run` wrote for the same scene and backends: the page loads with
// no console error and no network request, the canvas is not blank, stepping the timeline
// changes the picture, and for a known query and frame the highlighted pairs and triangles are
// the result file's.
// Environment: COLLIDO_VIEW_HTML (the page), COLLIDO_VIEW_RESULTS (collido run --json),
// COLLIDO_VIEW_QUERY and COLLIDO_VIEW_FRAME (the known frame), COLLIDO_VIEW_BOOLEAN_QUERY (a
// boolean query whose witnesses are checked in that frame), COLLIDO_VIEW_SCREENSHOT
// (optional: a picture of that frame, zoomed to the contacts, showing the difference for
// COLLIDO_VIEW_SCREENSHOT_BACKEND), CHROMIUM (default /usr/bin/chromium).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

const viewPath = process.env.COLLIDO_VIEW_HTML;
const resultsPath = process.env.COLLIDO_VIEW_RESULTS;
const queryName = process.env.COLLIDO_VIEW_QUERY;
const knownFrame = Number(process.env.COLLIDO_VIEW_FRAME);
const booleanQuery = process.env.COLLIDO_VIEW_BOOLEAN_QUERY;
const browserPath = process.env.CHROMIUM || '/usr/bin/chromium';

test('the view draws the scene and each backend\'s answers as the result file has them', async () => {
  for (const [name, value] of [['COLLIDO_VIEW_HTML', viewPath], ['COLLIDO_VIEW_RESULTS', resultsPath],
    ['COLLIDO_VIEW_QUERY', queryName], ['COLLIDO_VIEW_BOOLEAN_QUERY', booleanQuery]]) {
    assert.ok(value, `set ${name}`);
  }
  assert.ok(existsSync(viewPath), `${viewPath} does not exist`);
  assert.ok(existsSync(browserPath), `no browser at ${browserPath} (apt-get install chromium)`);
  const results = JSON.parse(readFileSync(resultsPath, 'utf8'));
  const browser = await chromium.launch({
    executablePath: browserPath,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
      '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync'],
  });
  try {
    const page = await browser.newPage({ viewport: { width: 1400, height: 850 } });
    const problems = [];
    page.on('console', (message) => {
      // Chromium's own WebGL driver notes on performance (software GL stalls on the pixel
      // read-back this test itself asks for, now and then) are not the page's problems.
      const driverNote = message.type() === 'warning' &&
        /^\[\.WebGL-[^\]]*\]GL Driver Message \([^)]*, Performance,/.test(message.text());
      if ((message.type() === 'error' || message.type() === 'warning') && !driverNote) {
        problems.push(`${message.type()}: ${message.text()}`);
      }
    });
    page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
    page.on('request', (request) => {
      const url = request.url();
      if (!url.startsWith('file:') && !url.startsWith('data:') && !url.startsWith('blob:')) {
        problems.push(`network request (the view must open offline): ${url}`);
      }
    });
    await page.goto(pathToFileURL(viewPath).href);
    await page.waitForFunction(() => document.body.getAttribute('data-ready') !== 'false',
      null, { timeout: 120000 });
    assert.equal(await page.evaluate(() => document.body.getAttribute('data-ready')), 'true',
      problems.join('\n'));

    // It opens at the first frame where the first query's exact answer has contact.
    const contactAt = results.measurements[0].frames.findIndex((f) => f.oracle_intersecting);
    assert.equal((await page.evaluate(() => window.collidoView.state())).frame,
      Math.max(0, contactAt));

    // Not blank: the meshes cover a good part of the canvas.
    const first = await page.evaluate(() => window.collidoView.pixels());
    assert.ok(first.drawn > 0.02 * first.width * first.height,
      `only ${first.drawn} of ${first.width * first.height} pixels drawn`);

    // Stepping the timeline changes the picture.
    const frames = results.measurements[0].frames.length;
    await page.evaluate((f) => window.collidoView.setFrame(f), frames - 1);
    const last = await page.evaluate(() => window.collidoView.pixels());
    assert.notEqual(last.hash, first.hash, 'the last frame looks like the first');
    await page.click('#prev');
    assert.equal((await page.evaluate(() => window.collidoView.state())).frame, frames - 2);

    // The known frame: every backend's highlighted pairs are the result file's, and the
    // triangles drawn in highlight colours are those the page counts.
    await page.evaluate((q) => window.collidoView.setQuery(q), queryName);
    await page.evaluate((f) => window.collidoView.setFrame(f), knownFrame);
    const backends = await page.evaluate(() => window.collidoView.backends());
    let checked = 0;
    for (const backend of backends) {
      const measurement = results.measurements.find((m) => m.backend === backend && m.query === queryName);
      assert.ok(measurement, `the result file has no ${backend} / ${queryName}`);
      await page.evaluate((b) => window.collidoView.setBackend(b), backend);
      for (const mode of ['difference', 'reported', 'oracle']) {
        await page.evaluate((m) => window.collidoView.setMode(m), mode);
        const shown = await page.evaluate(() => window.collidoView.state());
        const drawn = await page.evaluate(() => window.collidoView.drawnHighlights());
        if (!measurement.status.startsWith('ok')) {
          assert.equal(shown.highlighted, 0, `${backend} ${mode}: highlights without answers`);
          assert.ok(shown.status.startsWith('skipped') || shown.status.startsWith('failed'),
            `${backend}: status ${shown.status}`);
          continue;
        }
        const record = measurement.frames[knownFrame];
        assert.equal(shown.counts.reported, record.reported_pairs, `${backend} ${mode}: reported pairs`);
        assert.equal(shown.counts.oracle, record.oracle_pairs, `${backend} ${mode}: exact pairs`);
        if (mode === 'difference') {
          assert.equal(shown.counts.matched, record.matched_pairs, `${backend}: matched pairs`);
          assert.equal(shown.counts.missed, record.oracle_pairs - record.matched_pairs, `${backend}: missed`);
          assert.equal(shown.counts.extra, record.reported_pairs - record.matched_pairs, `${backend}: extra`);
        }
        const pairs = mode === 'oracle' ? record.oracle_pairs
          : mode === 'reported' ? record.reported_pairs
            : record.oracle_pairs + record.reported_pairs - record.matched_pairs;
        assert.equal(drawn, shown.highlighted, `${backend} ${mode}: triangles drawn highlighted`);
        assert.ok(pairs === 0 ? shown.highlighted === 0 : shown.highlighted > 0 && shown.highlighted <= 2 * pairs,
          `${backend} ${mode}: ${shown.highlighted} triangles for ${pairs} pairs`);
        const legend = await page.$eval('#highlighted-count', (n) => Number(n.textContent));
        assert.equal(legend, shown.highlighted, 'the legend shows the count');
        checked += 1;
      }
    }
    assert.ok(checked > 0, 'no backend answered the known query');

    // A boolean query names a witness, not every pair: its difference is of verdicts. A named
    // pair is drawn as extra exactly when it is a false witness (the runner's invalid pairs),
    // and the oracle's witness as missed exactly when the backend says apart at a contact.
    await page.evaluate((q) => window.collidoView.setQuery(q), booleanQuery);
    await page.evaluate(() => window.collidoView.setMode('difference'));
    let verdicts = 0;
    for (const backend of backends) {
      const measurement = results.measurements.find((m) => m.backend === backend && m.query === booleanQuery);
      assert.ok(measurement, `the result file has no ${backend} / ${booleanQuery}`);
      if (!measurement.status.startsWith('ok')) continue;
      await page.evaluate((b) => window.collidoView.setBackend(b), backend);
      const shown = await page.evaluate(() => window.collidoView.state());
      const record = measurement.frames[knownFrame];
      assert.equal(shown.counts.extra, record.invalid_pairs, `${backend} ${booleanQuery}: false witnesses`);
      assert.equal(shown.counts.matched + shown.counts.extra, shown.counts.reported,
        `${backend} ${booleanQuery}: every named pair is judged`);
      assert.equal(shown.counts.missed > 0, record.oracle_intersecting && !record.reported_intersecting,
        `${backend} ${booleanQuery}: the oracle's witness drawn as missed`);
      assert.equal(await page.evaluate(() => window.collidoView.drawnHighlights()), shown.highlighted);
      verdicts += 1;
    }
    assert.ok(verdicts > 0, `no backend answered ${booleanQuery}`);
    // At 1,400 pixels every answer keeps room to be read beside the longest backend name.
    const answerWidths = await page.evaluate(() =>
      [...document.querySelectorAll('#verdicts td.good, #verdicts td.bad')].map((td) => td.getBoundingClientRect().width));
    assert.ok(answerWidths.length > 0, 'no answers listed');
    assert.ok(Math.min(...answerWidths) >= 140, `answers squeezed to ${Math.min(...answerWidths)} px`);
    await page.evaluate((q) => window.collidoView.setQuery(q), queryName);

    // Clicking the middle of the contacts picks a triangle and lists its pairs.
    await page.evaluate((b) => window.collidoView.setBackend(b), backends[0]);
    await page.evaluate(() => window.collidoView.setMode('difference'));
    assert.ok(await page.evaluate(() => window.collidoView.focus()), 'nothing highlighted to zoom to');
    const picked = await page.evaluate(() => window.collidoView.pick(0, 0));
    assert.ok(picked, 'nothing under the middle of the zoomed contacts');
    const shownTriangle = await page.$eval('#picked-triangle', (n) => Number(n.textContent));
    assert.equal(shownTriangle, picked.triangle);
    if (process.env.COLLIDO_VIEW_SCREENSHOT) {
      const shown = process.env.COLLIDO_VIEW_SCREENSHOT_BACKEND || backends[0];
      await page.evaluate((b) => window.collidoView.setBackend(b), shown);
      await page.evaluate(() => window.collidoView.focus());
      await page.evaluate(() => window.collidoView.view([1, 0.55, 0.35]));
      await page.screenshot({ path: process.env.COLLIDO_VIEW_SCREENSHOT });
    }
    assert.deepEqual(problems, [], problems.join('\n'));
  } finally {
    await browser.close();
  }
});
