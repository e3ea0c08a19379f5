// Parses Mermaid diagrams with Mermaid's own parser (in Node, over jsdom), the code GitHub
// runs to render a ```mermaid block. Exit 0 when every file parses; otherwise prints the
// parse error of each failing file and exits 1 (2 on a usage error).
//   node parse-mermaid.mjs <folder with node_modules/mermaid> <file.mmd|file.md>...
// A .md file is parsed block by block (each ```mermaid fence).
import fs from 'fs';
import path from 'path';
import { pathToFileURL } from 'url';

const [modules, ...files] = process.argv.slice(2);
if (!modules || files.length === 0) {
  console.error('usage: parse-mermaid.mjs <modules dir> <file>...');
  process.exit(2);
}
const { JSDOM } = await import(pathToFileURL(path.join(modules, 'node_modules/jsdom/lib/api.js')).href);
const dom = new JSDOM('<!DOCTYPE html><body></body>', { pretendToBeVisual: true });
globalThis.window = dom.window;
globalThis.document = dom.window.document;
globalThis.DOMParser = dom.window.DOMParser;
globalThis.Element = dom.window.Element;
const mermaidEntry = JSON.parse(fs.readFileSync(path.join(modules, 'node_modules/mermaid/package.json'), 'utf8'));
const entry = mermaidEntry.exports?.['.']?.import ?? mermaidEntry.module ?? mermaidEntry.main;
const { default: mermaid } = await import(pathToFileURL(path.join(modules, 'node_modules/mermaid', typeof entry === 'string' ? entry : entry.default)).href);

let failed = 0;
for (const file of files) {
  const text = fs.readFileSync(file, 'utf8');
  const blocks = file.endsWith('.md')
    ? [...text.matchAll(/```mermaid\n([\s\S]*?)```/g)].map((m) => m[1])
    : [text];
  if (blocks.length === 0) {
    failed++;
    console.log(`${file}: no mermaid block`);
    continue;
  }
  for (const block of blocks) {
    try {
      await mermaid.parse(block);
    } catch (e) {
      failed++;
      console.log(`${file}: ${String(e.message || e).slice(0, 400)}`);
    }
  }
}
process.exit(failed ? 1 : 0);
