// Runs the Khronos glTF validator on one .gltf or .glb file, prints its report (JSON) and
// exits 1 when the report has errors, 2 when the file cannot be read or the tool is missing.
// Usage: node tests/tools/validate_gltf.mjs FILE
import { readFile } from 'node:fs/promises';
import path from 'node:path';

const file = process.argv[2];
if (!file) {
  console.error('usage: node validate_gltf.mjs FILE.gltf|FILE.glb');
  process.exit(2);
}
let validator;
try {
  validator = await import('gltf-validator');
} catch (e) {
  console.error(`gltf-validator is not installed (cd tests/tools && npm install): ${e.message}`);
  process.exit(2);
}
const { validateBytes } = validator.default ?? validator;
let bytes;
try {
  bytes = new Uint8Array(await readFile(file));
} catch (e) {
  console.error(`${file}: ${e.message}`);
  process.exit(2);
}
const directory = path.dirname(file);
const report = await validateBytes(bytes, {
  uri: path.basename(file),
  maxIssues: 100,
  // External resources (buffers, images) next to a .gltf.
  externalResourceFunction: (uri) =>
    readFile(path.join(directory, decodeURIComponent(uri))).then((data) => new Uint8Array(data)),
});
console.log(JSON.stringify(report, null, 2));
process.exit(report.issues.numErrors > 0 ? 1 : 0);
