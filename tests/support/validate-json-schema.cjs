// Validates JSON files against a JSON schema (draft 7) with @cfworker/json-schema, which
// scripts/fetch-sarif-schema.sh puts in the build tree. Exit 0 when every file is valid;
// otherwise prints the first errors of each invalid file and exits 1 (2 on a usage error).
//   node validate-json-schema.cjs <validator package dir> <schema.json> <file.json>...
'use strict';
const fs = require('fs');
const path = require('path');

const [validatorDir, schemaFile, ...files] = process.argv.slice(2);
if (!validatorDir || !schemaFile || files.length === 0) {
  console.error('usage: validate-json-schema.cjs <validator dir> <schema> <file>...');
  process.exit(2);
}
const { Validator } = require(path.resolve(validatorDir, 'dist/commonjs/index.js'));
const validator = new Validator(JSON.parse(fs.readFileSync(schemaFile, 'utf8')), '7', false);
let invalid = 0;
for (const file of files) {
  const result = validator.validate(JSON.parse(fs.readFileSync(file, 'utf8')));
  if (result.valid) continue;
  invalid++;
  console.log(`${file}: invalid`);
  for (const e of result.errors.slice(-12)) console.log(`  ${e.instanceLocation}: ${e.error}`);
}
process.exit(invalid ? 1 : 0);
