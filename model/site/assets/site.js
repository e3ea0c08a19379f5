// The architecture site's script (rosarch site): the search box, the search page and the
// findings filters. It reads window.rosarchSearchIndex (assets/search-index.js): a list of
// [name, kind, page, detail], pages relative to the site's root. No other script is loaded.
(function () {
  'use strict';
  var root = document.body.getAttribute('data-root') || '';
  var index = window.rosarchSearchIndex || [];

  function score(entry, query) {
    var name = entry[0].toLowerCase();
    if (name === query) return 0;
    if (name.indexOf(query) === 0) return 1;
    var at = name.indexOf(query);
    if (at < 0) return entry[3].toLowerCase().indexOf(query) >= 0 ? 4 : -1;
    return '/_.-: '.indexOf(name.charAt(at - 1)) >= 0 ? 2 : 3;
  }

  function search(text, limit) {
    var query = text.trim().toLowerCase();
    if (!query) return [];
    var found = [];
    for (var i = 0; i < index.length; i++) {
      var s = score(index[i], query);
      if (s >= 0) found.push([s, index[i]]);
    }
    found.sort(function (a, b) {
      return a[0] - b[0] || a[1][0].length - b[1][0].length ||
        (a[1][0] < b[1][0] ? -1 : a[1][0] > b[1][0] ? 1 : 0);
    });
    return found.slice(0, limit).map(function (f) { return f[1]; });
  }

  function item(entry) {
    var li = document.createElement('li');
    var a = document.createElement('a');
    a.href = root + entry[2];
    a.textContent = entry[0];
    var small = document.createElement('small');
    small.textContent = entry[1] + (entry[3] ? ' · ' + entry[3] : '');
    a.appendChild(small);
    li.appendChild(a);
    return li;
  }

  var box = document.getElementById('search-box');
  var list = document.getElementById('search-results');
  if (box && list) {
    var render = function () {
      var results = search(box.value, 12);
      list.textContent = '';
      results.forEach(function (e) { list.appendChild(item(e)); });
      list.hidden = results.length === 0;
    };
    box.addEventListener('input', render);
    box.addEventListener('keydown', function (event) {
      if (event.key === 'ArrowDown' && !list.hidden) {
        event.preventDefault();
        list.querySelector('a').focus();
      } else if (event.key === 'Escape') {
        list.hidden = true;
      }
    });
    list.addEventListener('keydown', function (event) {
      var links = Array.prototype.slice.call(list.querySelectorAll('a'));
      var at = links.indexOf(document.activeElement);
      if (event.key === 'ArrowDown' && at + 1 < links.length) {
        event.preventDefault();
        links[at + 1].focus();
      } else if (event.key === 'ArrowUp') {
        event.preventDefault();
        (at > 0 ? links[at - 1] : box).focus();
      } else if (event.key === 'Escape') {
        list.hidden = true;
        box.focus();
      }
    });
    document.addEventListener('click', function (event) {
      if (!list.contains(event.target) && event.target !== box) list.hidden = true;
    });
  }

  var params = new URLSearchParams(window.location.search);
  var page = document.getElementById('search-page-results');
  if (page && box) {
    var query = params.get('q') || '';
    box.value = query;
    var results = search(query, 500);
    results.forEach(function (e) { page.appendChild(item(e)); });
    var summary = document.getElementById('search-summary');
    if (query) summary.textContent = results.length + ' results for “' + query + '”';
  }

  var table = document.getElementById('findings');
  if (table) {
    var filters = Array.prototype.slice.call(document.querySelectorAll('[data-filter]'));
    var hidden = document.getElementById('show-hidden');
    var count = document.getElementById('finding-count');
    var rows = Array.prototype.slice.call(table.tBodies[0].rows);
    var apply = function () {
      var shown = 0;
      rows.forEach(function (row) {
        var ok = hidden.checked || row.getAttribute('data-mark') !== 'hidden';
        filters.forEach(function (f) {
          if (!f.value) return;
          var name = f.getAttribute('data-filter');
          var value = row.getAttribute('data-' + (name === 'system' ? 'systems' : name)) || '';
          if (name === 'system' ? value.split('\n').indexOf(f.value) < 0 : value !== f.value) ok = false;
        });
        row.hidden = !ok;
        shown += ok ? 1 : 0;
      });
      count.textContent = shown + ' of ' + rows.length + ' shown';
    };
    filters.forEach(function (f) {
      var wanted = params.get(f.getAttribute('data-filter'));
      if (wanted) f.value = wanted;
      f.addEventListener('change', apply);
    });
    hidden.addEventListener('change', apply);
    apply();
  }

  // A diagram wider than the page is shown whole; a button shows it at its actual size.
  Array.prototype.forEach.call(document.querySelectorAll('figure.diagram-wrap'), function (figure) {
    var svg = figure.querySelector('svg.diagram');
    var caption = figure.querySelector('figcaption');
    var scroll = figure.querySelector('.scroll');
    if (!svg || !caption || !scroll || svg.width.baseVal.value <= scroll.clientWidth) return;
    var button = document.createElement('button');
    button.type = 'button';
    button.className = 'zoom';
    button.textContent = 'Actual size';
    button.setAttribute('aria-pressed', 'false');
    button.addEventListener('click', function () {
      var actual = figure.classList.toggle('actual');
      button.setAttribute('aria-pressed', actual ? 'true' : 'false');
    });
    caption.appendChild(button);
  });

  // A printed page shows what its folded sections hold.
  window.addEventListener('beforeprint', function () {
    Array.prototype.forEach.call(document.querySelectorAll('details'), function (d) { d.open = true; });
  });
})();
