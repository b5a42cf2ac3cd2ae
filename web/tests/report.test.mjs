// Opens a report made by `collido report` in headless Chromium and checks that every chart was
// drawn and the page logged no error. The report's path comes from COLLIDO_REPORT_HTML; the
// browser from CHROMIUM (default /usr/bin/chromium).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync, readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

const reportPath = process.env.COLLIDO_REPORT_HTML;
const browserPath = process.env.CHROMIUM || '/usr/bin/chromium';
const expectedViews = (process.env.COLLIDO_EXPECT_VIEWS || '').split(',').filter(Boolean);
// "section=text,...": text each named section must show (e.g. robustness=unsupported: a question
// a backend does not answer is labelled so in the matrix, never drawn as zero errors).
const expectedTexts = (process.env.COLLIDO_EXPECT_SECTION_TEXT || '').split(',').filter(Boolean)
  .map((pair) => pair.split('='));
// The study's table.txt: its "What to pick" rows must name the settings the page names.
const tableTxt = process.env.COLLIDO_TABLE_TXT;
// A bound on the time from opening the page to every chart drawn, for checks on a quiet machine
// (tools/check_report.sh); the suite's run on a busy CI machine sets none.
const loadLimitMs = Number(process.env.COLLIDO_REPORT_LOAD_LIMIT_MS || 0);
const MAX_LEGEND_ENTRIES = 10;

const escapeRegExp = (text) => text.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');
// The "What to pick" lines of table.txt, between its title and the empty line after the notes.
function textPicks(text) {
  const lines = text.split('\n');
  const start = lines.indexOf('What to pick (per scene and query):');
  assert.ok(start >= 0, 'table.txt has no "What to pick" section');
  const rows = [];
  for (const line of lines.slice(start + 3)) {
    if (line.startsWith('Per scene and query')) break;
    rows.push(line);
  }
  return rows;
}

test('every chart of the report renders without console errors', async () => {
  assert.ok(reportPath, 'set COLLIDO_REPORT_HTML to the report to open');
  assert.ok(existsSync(reportPath), `${reportPath} does not exist`);
  assert.ok(existsSync(browserPath), `no browser at ${browserPath} (apt-get install chromium)`);
  const browser = await chromium.launch({
    executablePath: browserPath,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  try {
    const page = await browser.newPage();
    const problems = [];
    page.on('console', (message) => {
      if (message.type() === 'error' || message.type() === 'warning') {
        problems.push(`${message.type()}: ${message.text()}`);
      }
    });
    page.on('pageerror', (error) => problems.push(`page error: ${error.message}`));
    page.on('request', (request) => {
      if (!request.url().startsWith('file:') && !request.url().startsWith('data:')) {
        problems.push(`network request (the report must open offline): ${request.url()}`);
      }
    });
    const opened = Date.now();
    await page.goto(pathToFileURL(reportPath).href);
    await page.waitForFunction(() => document.body.getAttribute('data-ready') === 'true',
      null, { timeout: 120000 });
    const loadMs = Date.now() - opened;
    console.log(`report ready in ${loadMs} ms`);
    if (loadLimitMs > 0) {
      assert.ok(loadMs < loadLimitMs, `the report took ${loadMs} ms to show, over ${loadLimitMs} ms`);
    }
    if (process.env.COLLIDO_REPORT_TOP_SCREENSHOT) {
      await page.setViewportSize({ width: 1400, height: 1000 });
      await page.screenshot({ path: process.env.COLLIDO_REPORT_TOP_SCREENSHOT });
    }
    // The charts further down are drawn as they come into view; draw them all to check them.
    const drawnAt = Date.now();
    await page.evaluate(() => window.COLLIDO_REPORT.renderAll());
    console.log(`every chart drawn ${Date.now() - drawnAt} ms later`);

    if (process.env.COLLIDO_REPORT_SCREENSHOT) {
      await page.setViewportSize({ width: 1300, height: 900 });
      await page.screenshot({ path: process.env.COLLIDO_REPORT_SCREENSHOT, fullPage: true });
    }
    const charts = await page.$$eval('.chart', (nodes) => nodes.map((n) => ({
      view: n.getAttribute('data-view'),
      rendered: n.getAttribute('data-rendered'),
      error: n.getAttribute('data-error'),
      marks: n.querySelectorAll('svg .mark-symbol path, svg .mark-rect path, svg .mark-line path, ' +
        'svg .mark-group path, svg path').length,
    })));
    assert.ok(charts.length > 0, 'the report has no chart');
    for (const c of charts) {
      assert.equal(c.error, null, `chart ${c.view} failed: ${c.error}`);
      assert.equal(c.rendered, 'true', `chart ${c.view} was not rendered`);
      assert.ok(c.marks > 0, `chart ${c.view} drew nothing`);
    }
    for (const view of expectedViews) {
      assert.ok(charts.some((c) => c.view.startsWith(view)), `no chart for view ${view}`);
    }
    const sections = await page.$$eval('section.view', (nodes) => nodes.map((n) => n.id));
    // Inlined pictures (the FRep previews) decoded: a broken data URI leaves them 0 wide.
    const pictures = await page.$$eval('img', (nodes) => nodes.map((n) => ({
      view: n.getAttribute('data-view'), width: n.naturalWidth })));
    for (const p of pictures) assert.ok(p.width > 0, `picture ${p.view} did not decode`);
    for (const id of ['time-vs-error', 'distance-error', 'contact-error', 'surfaces', 'frep', 'robustness', 'time-distributions', 'deforming', 'tracking',
      'pose-error', 'memory', 'scaling',
      'failures', 'scene-views', 'needs', 'comparison', 'table']) {
      assert.ok(sections.includes(id), `missing section ${id}`);
    }
    // Links to scene views lead to files beside the report.
    const links = await page.$$eval('#scene-views a', (nodes) => nodes.map((n) => n.href));
    for (const link of links) {
      assert.ok(link.startsWith('file:') && existsSync(new URL(link)), `view link ${link} is broken`);
    }
    // A single offline file: every script, style and picture inline.
    const external = await page.$$eval('script[src], link[href], img', (nodes) => nodes
      .map((n) => n.getAttribute('src') || n.getAttribute('href') || '')
      .filter((url) => !url.startsWith('data:')));
    assert.deepEqual(external, [], 'the report loads files beside it');
    // No legend of more than a handful of entries.
    const legends = await page.$$eval('.chart', (nodes) => nodes.map((n) => ({
      view: n.getAttribute('data-view'),
      entries: n.querySelectorAll('.role-legend-symbol path').length })));
    for (const l of legends) {
      assert.ok(l.entries <= MAX_LEGEND_ENTRIES, `chart ${l.view} has ${l.entries} legend entries`);
    }
    // The table of every row has table.txt's measurement columns, declared once.
    if (tableTxt) {
      const header = readFileSync(tableTxt, 'utf8').split('\n')
        .find((line) => line.startsWith('backend') && line.includes('mean us [95% CI]'));
      assert.ok(header, 'table.txt has no table of every setting');
      const columns = header.trim().split(/ {2,}/);
      const pageColumns = await page.$$eval('#table th', (nodes) => nodes.map((n) => n.textContent));
      assert.deepEqual(pageColumns.slice(4), columns.slice(4, columns.indexOf('RSS MiB')),
        'the page and table.txt show different measurement columns');
    }
    // The header's counts lead to their lists.
    const countLinks = await page.$$eval('#counts a', (nodes) => nodes.map((n) => n.getAttribute('href')));
    // Three counts, and a fourth where the plan left settings out of scenes (as table.txt says).
    const leftOut = tableTxt && readFileSync(tableTxt, 'utf8').includes('Not applicable, so not planned');
    assert.equal(countLinks.length, leftOut ? 4 : 3, 'the header does not give its counts');
    if (leftOut) assert.equal(countLinks[3], '#not-applicable');
    for (const href of countLinks) {
      assert.ok(await page.$(href), `the header links to ${href}, which is missing`);
    }
    // The page's picks, at the default budget, are table.txt's.
    if (tableTxt) {
      const lines = textPicks(readFileSync(tableTxt, 'utf8'));
      const picks = await page.$$eval('#what-to-pick tr.pick', (rows) => rows.map((r) => ({
        scene: r.getAttribute('data-scene'), query: r.getAttribute('data-query'),
        names: ['fastest-exact', 'fastest-within', 'smallest-exact'].map(
          (k) => r.querySelector(`[data-pick="${k}"]`).textContent) })));
      assert.equal(picks.length, lines.length, 'the page and table.txt list different scenes');
      picks.forEach((p, i) => {
        const [exact, within, smallest] = p.names.map(escapeRegExp);
        const row = new RegExp(`^${escapeRegExp(p.scene)}\\s+${escapeRegExp(p.query)}\\s+${exact}\\s.*` +
          `\\s${within}\\s.*\\s${smallest}\\s+\\S+\\s+\\S+$`);
        assert.match(lines[i], row, `table.txt and the page pick differently for ${p.scene} ${p.query}`);
      });
    }
    // Holding all pairs to a pair recall and precision of 0% admits every all-pairs setting: the
    // budget's pick is then the fastest of all, tied ("P ≈ T1, T2") with every other setting it
    // is not clearly faster than, fastest first.
    await page.fill('#pick-pair-floor', '0');
    const floorPicks = await page.evaluate(() => {
      const data = JSON.parse(document.getElementById('collido-data').textContent);
      const rows = [...document.querySelectorAll('#what-to-pick tr.pick')];
      return ((data.what_to_pick && data.what_to_pick.picks) || []).map((p, i) => {
        const pairs = p.settings.filter((o) => o.recall !== null);
        if (pairs.length === 0) return null;
        const fastest = pairs.reduce((a, b) => (b.mean_us < a.mean_us ? b : a));
        const ties = pairs.filter((o) => o !== fastest &&
          !(fastest.clearly_faster_than || []).includes(o.backend))
          .sort((a, b) => a.mean_us - b.mean_us).map((o) => o.backend);
        return [p.scene + ' ' + p.query,
          fastest.backend + (ties.length ? ' ≈ ' + ties.join(', ') : ''),
          rows[i].querySelector('[data-pick="fastest-within"]').textContent];
      }).filter(Boolean);
    });
    for (const [row, expected, shown] of floorPicks) {
      assert.equal(shown, expected, `with no pair floor, ${row} does not pick its fastest setting`);
    }
    await page.fill('#pick-pair-floor', '');
    // The filters select in every chart without a reload and without a warning.
    const total = await page.$$eval('.chart', (nodes) => nodes.filter((n) => n.offsetParent !== null).length);
    const families = await page.$$eval('#filter-family option', (os) => os.map((o) => o.value));
    await page.selectOption('#filter-family', families[families.length - 1]);
    await page.check('#filter-exact');
    await page.selectOption('#filter-query', 'boolean');
    await page.waitForTimeout(500);
    const filtered = await page.$$eval('.chart', (nodes) => nodes.filter((n) => n.offsetParent !== null).length);
    assert.ok(filtered < total, `filtering left every chart (${filtered} of ${total})`);
    await page.selectOption('#filter-family', 'all');
    await page.uncheck('#filter-exact');
    await page.selectOption('#filter-query', 'all');
    await page.waitForTimeout(500);
    const restored = await page.$$eval('.chart', (nodes) => nodes.filter((n) => n.offsetParent !== null).length);
    assert.equal(restored, total, 'clearing the filters did not bring every chart back');
    for (const [id, text] of expectedTexts) {
      const shown = await page.$eval('#' + id, (n) => n.textContent);
      assert.ok(shown.includes(text), `section ${id} does not show "${text}"`);
    }
    // Log axes keep their labels apart, and no axis shows a lone "0.000000".
    const crowded = await page.$$eval('.chart svg', (svgs) => {
      const found = [];
      for (const svg of svgs) {
        for (const axis of svg.querySelectorAll('.role-axis-label')) {
          const boxes = [...axis.querySelectorAll('text')].filter((t) => t.getAttribute('opacity') !== '0')
            .map((t) => t.getBoundingClientRect()).filter((b) => b.width > 0);
          for (let i = 1; i < boxes.length; ++i) {
            const a = boxes[i - 1];
            const b = boxes[i];
            const apart = a.right <= b.left || b.right <= a.left || a.bottom <= b.top || b.bottom <= a.top;
            if (!apart) found.push(svg.closest('[data-view]').getAttribute('data-view'));
          }
        }
      }
      return found;
    });
    assert.deepEqual(crowded, [], `axis labels overlap in ${crowded.join(', ')}`);
    const zeros = await page.$$eval('.role-axis-label text', (ts) => ts.map((t) => t.textContent)
      .filter((t) => /^0\.0{4,}$/.test(t)));
    assert.deepEqual(zeros, [], 'an axis shows a long zero tick');
    assert.deepEqual(problems, [], problems.join('\n'));
  } finally {
    await browser.close();
  }
});
