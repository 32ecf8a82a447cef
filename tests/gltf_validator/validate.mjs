// Runs the Khronos glTF-Validator on one .gltf or .glb file.
//
//   node validate.mjs FILE
//
// Prints one JSON object to stdout: {"errors", "warnings", "infos", "hints",
// "messages": [{"severity", "code", "pointer", "message"}]}, a one-line
// summary to stderr, and exits 0 only when there is no error and no
// warning (1 otherwise, 2 when the file could not be validated at all).
// Resources a .gltf refers to (buffers, images) are read from its folder.
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import validator from 'gltf-validator';

const severities = ['error', 'warning', 'info', 'hint'];

async function main() {
  const file = process.argv[2];
  if (!file) {
    console.error('usage: node validate.mjs FILE.gltf|FILE.glb');
    return 2;
  }
  const folder = path.dirname(path.resolve(file));
  const report = await validator.validateBytes(new Uint8Array(await readFile(file)), {
    uri: path.basename(file),
    maxIssues: 0,  // report every issue, not the first hundred
    writeTimestamp: false,
    externalResourceFunction: async (uri) =>
      new Uint8Array(await readFile(path.resolve(folder, decodeURIComponent(uri)))),
  });
  const issues = report.issues;
  const summary = {
    errors: issues.numErrors,
    warnings: issues.numWarnings,
    infos: issues.numInfos,
    hints: issues.numHints,
    messages: issues.messages.map((m) => ({
      severity: severities[m.severity] ?? String(m.severity),
      code: m.code,
      pointer: m.pointer ?? '',
      message: m.message,
    })),
  };
  console.log(JSON.stringify(summary));
  console.error(`${file}: ${summary.errors} errors, ${summary.warnings} warnings, ` +
                `${summary.infos} infos, ${summary.hints} hints (glTF-Validator ${validator.version()})`);
  return summary.errors === 0 && summary.warnings === 0 ? 0 : 1;
}

main().then((code) => { process.exitCode = code; },
            (error) => { console.error(`${process.argv[2]}: cannot validate: ${error}`); process.exitCode = 2; });
