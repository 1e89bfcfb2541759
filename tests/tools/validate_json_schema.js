#!/usr/bin/env node
// Validates a JSON file against a JSON Schema (draft-07) with Ajv.
// Usage: validate_json_schema.js SCHEMA.json FILE.json
// Exit 0 valid, 1 invalid (every error printed with its path), 2 on a
// usage or I/O problem.
'use strict';
const fs = require('fs');
const Ajv = require('ajv');

const [schemaFile, dataFile] = process.argv.slice(2);
if (!schemaFile || !dataFile) {
  console.error('usage: validate_json_schema.js SCHEMA.json FILE.json');
  process.exit(2);
}
let schema, data;
try {
  schema = JSON.parse(fs.readFileSync(schemaFile, 'utf8'));
  data = JSON.parse(fs.readFileSync(dataFile, 'utf8'));
} catch (e) {
  console.error(`cannot read: ${e.message}`);
  process.exit(2);
}
const ajv = new Ajv({ allErrors: true, strict: true });
const validate = ajv.compile(schema);
if (validate(data)) {
  console.log(`${dataFile}: valid against ${schemaFile}`);
  process.exit(0);
}
for (const e of validate.errors) console.log(`${dataFile}${e.instancePath || '/'}: ${e.message}`);
process.exit(1);
