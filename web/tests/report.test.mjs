// Opens a report made by `collido report` in headless Chromium and checks that every chart was
// drawn and the page logged no error. The report's path comes from COLLIDO_REPORT_HTML; the
// browser from CHROMIUM (default /usr/bin/chromium).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { existsSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

const reportPath = process.env.COLLIDO_REPORT_HTML;
const browserPath = process.env.CHROMIUM || '/usr/bin/chromium';
const expectedViews = (process.env.COLLIDO_EXPECT_VIEWS || '').split(',').filter(Boolean);
// "section=text,...": text each named section must show (e.g. robustness=unsupported: a question
// a backend does not answer is labelled so in the matrix, never drawn as zero errors).
const expectedTexts = (process.env.COLLIDO_EXPECT_SECTION_TEXT || '').split(',').filter(Boolean)
  .map((pair) => pair.split('='));

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
    await page.goto(pathToFileURL(reportPath).href);
    await page.waitForFunction(() => document.body.getAttribute('data-ready') === 'true',
      null, { timeout: 60000 });

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
