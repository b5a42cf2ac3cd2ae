// DOM helpers: elements, the page's sections (each linked from the table of contents), tables,
// and what is built late: when it comes near the window, or when renderAll() asks for everything.
const ReportDom = (() => {
  'use strict';
  const views = document.getElementById('views');
  const toc = document.getElementById('toc');

  // --- built late -----------------------------------------------------------------------------
  // A full study has hundreds of charts: each is drawn when it comes near the window.
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
  // `start` fills `holder` (returning a promise of its end) once the holder comes near the
  // window; at once where the browser cannot tell.
  function later(holder, start) {
    waiting.set(holder, start);
    if (near) near.observe(holder); else draw(holder);
  }
  // Everything still waiting, now; the promise ends when all is drawn.
  const renderAll = () => {
    for (const holder of [...waiting.keys()]) draw(holder);
    return Promise.all(drawing);
  };
  // The promise that what has started drawing so far is drawn.
  const drawn = () => Promise.all(drawing);

  // --- elements -------------------------------------------------------------------------------
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
  // A table of many rows is built when it comes near the window (COLLIDO_REPORT.renderAll()
  // builds it too): thousands of rows would hold up the first screen.
  function laterTable(parent, header, rows, classes) {
    if (rows.length < 200) return table(parent, header, rows, classes);
    const holder = el('div', { class: 'waiting-table', text: `${rows.length} rows` });
    parent.appendChild(holder);
    later(holder, () => {
      holder.textContent = '';
      holder.classList.remove('waiting-table');
      table(holder, header, rows, classes);
      return Promise.resolve();
    });
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

  return { el, section, table, laterTable, empty, later, renderAll, drawn };
})();
