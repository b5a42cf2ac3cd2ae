// Scenes in 3D: links to each scene's view (collido view) written beside the study.
const ReportSceneViews = (() => {
  'use strict';
  const { el, section, empty } = ReportDom;

  function render(model) {
    const s = section('scene-views', 'Scenes in 3D',
      'Each scene\'s 3D view (collido view): the meshes frame by frame and, for each backend ' +
      'the study ran on it, the triangles it reports as intersecting, the exact oracle\'s, and ' +
      'the pairs it missed or added.');
    const views = model.data.views || [];
    if (views.length === 0) {
      empty(s, 'No views beside this study (tools/study.sh writes them into views/).');
      return;
    }
    const list = el('ul', { class: 'view-links' });
    for (const v of views) {
      const item = el('li');
      item.appendChild(el('a', { href: v.href, text: v.scene, 'data-scene': v.scene }));
      list.appendChild(item);
    }
    s.appendChild(list);
  }

  return { render };
})();
