// Numbers and times as the dashboard writes them: table.txt's rounding, and the study's one time
// statistic with its 95% interval, as text and as a chart's fields.
const ReportFormat = (() => {
  'use strict';
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

  return { fixed, fmt, timeOf, ciOf, withInterval, timeFields, TIME_TITLE };
})();
