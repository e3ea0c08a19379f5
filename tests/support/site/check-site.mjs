// Checks a site written by `rosarch site` in a real browser and with the validators the
// tests install (scripts/fetch-site-tools.sh): every internal link resolves (pages, fragments
// and source files), the search finds the names asked for and leads to their pages, a click
// on a part of a system diagram lands on its node page, the HTML validates with the Nu HTML
// Checker, and axe-core finds no serious or critical violation. Writes screenshots and prints
// a JSON report on stdout; the C++ test judges it.
//
// node check-site.mjs <site dir> <screenshot dir> <chromium> <vnu.jar> <java> <search terms...>
// A search term is "text=page" (the page the first result for text must lead to, site-relative).
import fs from 'node:fs';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { pathToFileURL, fileURLToPath } from 'node:url';

const require = createRequire(process.env.ROSARCH_SITE_TOOLS + '/package.json');
const puppeteer = require('puppeteer-core');
const axePath = require.resolve('axe-core/axe.min.js');

const [site, shots, chromium, vnuJar, java, ...terms] = process.argv.slice(2);
const siteRoot = path.resolve(site);
const report = {
  pages: 0, links: 0, brokenLinks: [], sourceLinks: 0, brokenSourceLinks: [],
  search: [], diagramClick: null, keyboard: null, axe: [], vnu: [], vnuChecked: 0, screenshots: [],
};
fs.mkdirSync(shots, { recursive: true });

function htmlFiles(dir) {
  const out = [];
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const p = path.join(dir, entry.name);
    if (entry.isDirectory()) out.push(...htmlFiles(p));
    else if (entry.name.endsWith('.html')) out.push(p);
  }
  return out.sort();
}

const files = htmlFiles(siteRoot);
report.pages = files.length;

// The Nu HTML Checker on every page, in batches (one JVM start each).
for (let i = 0; i < files.length; i += 400) {
  const batch = files.slice(i, i + 400);
  const r = spawnSync(java, ['-jar', vnuJar, '--errors-only', '--format', 'json', ...batch],
    { encoding: 'utf8', maxBuffer: 256 * 1024 * 1024 });
  report.vnuChecked += batch.length;
  if (r.error || r.status === null) {
    report.vnu.push(`vnu could not run: ${r.error || r.signal}`);
    continue;
  }
  try {
    for (const m of JSON.parse(r.stderr || '{"messages":[]}').messages)
      report.vnu.push(`${path.relative(siteRoot, fileURLToPath(m.url || pathToFileURL(siteRoot).href))}:${m.lastLine}: ${m.message}`);
    if (r.status !== 0 && !report.vnu.length) report.vnu.push(`vnu failed (exit ${r.status}) without a message`);
  } catch (e) {
    report.vnu.push(`vnu did not report JSON (exit ${r.status}): ${(r.stderr || '').slice(0, 500)}`);
  }
}

const browser = await puppeteer.launch({
  executablePath: chromium, headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--allow-file-access-from-files'],
});
const idsOf = new Map(); // page file -> Set of ids
const linksOf = new Map(); // page file -> [absolute href]

async function collect(page, file) {
  await page.goto(pathToFileURL(file).href, { waitUntil: 'load' });
  const found = await page.evaluate(() => ({
    ids: Array.from(document.querySelectorAll('[id]'), (e) => e.id),
    links: Array.from(document.querySelectorAll('a[href], svg a'), (a) =>
      a.href && typeof a.href === 'object' ? new URL(a.href.baseVal, document.baseURI).href : a.href),
  }));
  idsOf.set(file, new Set(found.ids));
  linksOf.set(file, found.links);
}

// Visit every page in a few tabs at once.
const queue = files.slice();
await Promise.all([0, 1, 2, 3].map(async () => {
  const page = await browser.newPage();
  while (queue.length) await collect(page, queue.shift());
  await page.close();
}));
for (const [file, links] of linksOf) {
  for (const href of links) {
    const url = new URL(href);
    if (url.protocol !== 'file:') continue;
    const target = fileURLToPath(url);
    const inside = target.startsWith(siteRoot + path.sep);
    if (inside) report.links++; else report.sourceLinks++;
    const where = path.relative(siteRoot, file);
    if (!fs.existsSync(target)) {
      (inside ? report.brokenLinks : report.brokenSourceLinks).push(`${where} -> ${href}`);
      continue;
    }
    const fragment = decodeURIComponent(url.hash.slice(1));
    if (inside && fragment && target.endsWith('.html') && !(idsOf.get(target) || new Set()).has(fragment))
      report.brokenLinks.push(`${where} -> ${href} (no such id)`);
  }
}

const page = await browser.newPage();
await page.setViewport({ width: 1366, height: 900 });
async function shot(name) {
  const file = path.join(shots, name + '.png');
  await page.screenshot({ path: file, fullPage: false });
  report.screenshots.push(file);
}

// Search: type each name into the box on the index; the first result must lead to its page.
const index = pathToFileURL(path.join(siteRoot, 'index.html')).href;
for (const term of terms) {
  const [text, expected] = term.split('=');
  await page.goto(index, { waitUntil: 'load' });
  await page.type('#search-box', text);
  await page.waitForSelector('#search-results li a', { timeout: 5000 }).catch(() => {});
  const results = await page.$$eval('#search-results li a', (as) => as.map((a) => a.href));
  const entry = { text, expected, results: results.length, landed: '' };
  if (results.length) {
    if (report.search.length === 0) await shot('search-results');
    await Promise.all([page.waitForNavigation({ waitUntil: 'load' }), page.click('#search-results li a')]);
    entry.landed = path.relative(siteRoot, fileURLToPath(page.url()));
  }
  report.search.push(entry);
}

// The first system page: screenshot, then click the first node part of its diagram.
const systems = files.filter((f) => f.includes(`${path.sep}systems${path.sep}`));
if (systems.length) {
  await page.goto(pathToFileURL(systems[0]).href, { waitUntil: 'load' });
  await shot('system');
  const part = await page.$('svg.diagram g.part:not(.include) > a');
  if (part) {
    const href = await page.evaluate((a) => a.getAttribute('href'), part);
    await part.evaluate((a) => a.scrollIntoView({ block: 'center', inline: 'center' }));
    await Promise.all([page.waitForNavigation({ waitUntil: 'load' }), part.click()]);
    report.diagramClick = {
      from: path.relative(siteRoot, systems[0]), href,
      landed: path.relative(siteRoot, fileURLToPath(page.url())),
      heading: await page.$eval('h1', (h) => h.textContent),
    };
    await shot('node-from-diagram');
  } else {
    report.diagramClick = { from: path.relative(siteRoot, systems[0]), href: '', landed: '', heading: '' };
  }
}

// Keyboard: Tab from the top of the system page reaches a link of its diagram; Enter follows it.
if (systems.length) {
  await page.goto(pathToFileURL(systems[0]).href, { waitUntil: 'load' });
  const keyboard = { reached: false, presses: 0, landed: '' };
  while (keyboard.presses < 100 && !keyboard.reached) {
    await page.keyboard.press('Tab');
    keyboard.presses++;
    keyboard.reached = await page.evaluate(() =>
      !!(document.activeElement && document.activeElement.closest('svg.diagram a')));
  }
  if (keyboard.reached) {
    await Promise.all([page.waitForNavigation({ waitUntil: 'load', timeout: 5000 }).catch(() => {}),
      page.keyboard.press('Enter')]);
    const url = new URL(page.url());
    keyboard.landed = path.relative(siteRoot, fileURLToPath(url.href.split('#')[0])) + url.hash;
  }
  report.keyboard = keyboard;
}

// Screenshots a person looks at: laptop, phone, dark scheme, print.
await page.goto(index, { waitUntil: 'load' });
await shot('index');
await page.emulateMediaFeatures([{ name: 'prefers-color-scheme', value: 'dark' }]);
await shot('index-dark');
if (systems.length) {
  await page.goto(pathToFileURL(systems[0]).href, { waitUntil: 'load' });
  await shot('system-dark');
}
await page.emulateMediaFeatures([{ name: 'prefers-color-scheme', value: 'light' }]);
const findings = path.join(siteRoot, 'findings.html');
await page.goto(pathToFileURL(findings).href, { waitUntil: 'load' });
await shot('findings');
await page.setViewport({ width: 390, height: 844, deviceScaleFactor: 2, isMobile: true, hasTouch: true });
const nodePages = files.filter((f) => f.includes(`${path.sep}nodes${path.sep}`));
if (nodePages.length) {
  await page.goto(pathToFileURL(nodePages[0]).href, { waitUntil: 'load' });
  await shot('node-phone');
}
await page.goto(index, { waitUntil: 'load' });
await shot('index-phone');
await page.setViewport({ width: 1100, height: 1400 });
await page.emulateMediaType('print');
if (systems.length) {
  await page.goto(pathToFileURL(systems[0]).href, { waitUntil: 'load' });
  await shot('system-print');
}
await page.emulateMediaType('screen');
await page.setViewport({ width: 1366, height: 900 });

// axe-core on one page of each kind, in the light and the dark scheme.
const kinds = ['index.html', 'findings.html', 'search.html', 'systems', 'nodes', 'topics', 'services',
  'actions', 'launch', 'packages'];
const sample = [];
for (const k of kinds) {
  const f = k.endsWith('.html') ? path.join(siteRoot, k) : files.find((x) => x.includes(`${path.sep}${k}${path.sep}`));
  if (f && fs.existsSync(f)) sample.push(f);
}
for (const scheme of ['light', 'dark']) {
  await page.emulateMediaFeatures([{ name: 'prefers-color-scheme', value: scheme }]);
  for (const f of sample) {
    await page.goto(pathToFileURL(f).href, { waitUntil: 'load' });
    await page.addScriptTag({ path: axePath });
    const result = await page.evaluate(async () => {
      // eslint-disable-next-line no-undef
      const r = await axe.run(document, { resultTypes: ['violations'] });
      return r.violations.map((v) => ({ id: v.id, impact: v.impact, help: v.help,
        nodes: v.nodes.slice(0, 3).map((n) => n.target.join(' ')) }));
    });
    report.axe.push({ page: path.relative(siteRoot, f), scheme, violations: result });
  }
}
await browser.close();
process.stdout.write(JSON.stringify(report, null, 1) + '\n');
