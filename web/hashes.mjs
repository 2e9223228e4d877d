// Cross-platform determinism: runs every case of the determinism-check crate in its wasm32
// build under Node.js's V8 and prints one line per case, as the native binary does:
// its name, a space, and its hash as 16 hexadecimal digits.
//
// Usage: node web/hashes.mjs WASM [NATIVE]
//   WASM    the crate's release .wasm (bash web/cargo-wasm.sh --release -p determinism-check --lib)
//   NATIVE  optional: the native binary's output (cargo run --release -p determinism-check);
//           every wasm32 hash must equal the native one of the same case, bit for bit.
// The lines go to standard output; the comparison's verdict, any difference (the case and
// both hashes) and the timings go to standard error. Exit status: 0 when all is equal, 1 on
// a difference or a run that failed, 2 on bad usage or unreadable files.
import { readFile } from "node:fs/promises";

function fail(status, message) {
  process.stderr.write(`hashes: ${message}\n`);
  process.exit(status);
}

async function readOrFail(path, what) {
  try {
    return await readFile(path);
  } catch (error) {
    return fail(2, `cannot read the ${what} ${path}: ${error.message}`);
  }
}

// "name hash" lines into a Map, refusing anything else.
function parseList(text, path) {
  const hashes = new Map();
  text.split("\n").forEach((line, index) => {
    if (line === "") return;
    const match = /^(\S+) ([0-9a-f]{16})$/.exec(line);
    if (!match) fail(2, `${path}:${index + 1}: not a "name hash" line: ${JSON.stringify(line)}`);
    if (hashes.has(match[1])) fail(2, `${path}:${index + 1}: case ${match[1]} listed twice`);
    hashes.set(match[1], match[2]);
  });
  return hashes;
}

async function instantiate(path) {
  const bytes = await readOrFail(path, "wasm module");
  let module;
  try {
    module = await WebAssembly.compile(bytes);
  } catch (error) {
    return fail(2, `${path} is not a wasm module: ${error.message}`);
  }
  const imports = WebAssembly.Module.imports(module);
  if (imports.length > 0) {
    const names = imports.map((i) => `${i.module}.${i.name}`).join(", ");
    fail(2, `${path} needs imports (${names}); the determinism module must need none`);
  }
  const exports = (await WebAssembly.instantiate(module, {})).exports;
  for (const name of ["memory", "determinism_case_count", "determinism_case_name_ptr",
    "determinism_case_name_len", "determinism_case_hash"]) {
    if (!(name in exports)) fail(2, `${path} does not export ${name}`);
  }
  return exports;
}

function caseName(exports, index) {
  const pointer = exports.determinism_case_name_ptr(index);
  const length = exports.determinism_case_name_len(index);
  return new TextDecoder().decode(new Uint8Array(exports.memory.buffer, pointer, length));
}

const [wasmPath, nativePath, ...extra] = process.argv.slice(2);
if (!wasmPath || extra.length > 0) fail(2, "usage: node web/hashes.mjs WASM [NATIVE]");
const native = nativePath
  ? parseList((await readOrFail(nativePath, "native list")).toString("utf8"), nativePath)
  : null;

const exports = await instantiate(wasmPath);
const count = exports.determinism_case_count();
const wasm = new Map();
const problems = [];
const started = performance.now();
for (let index = 0; index < count; index++) {
  const name = caseName(exports, index);
  try {
    // A u64 result reaches JavaScript as a signed i64 BigInt.
    const hash = BigInt.asUintN(64, exports.determinism_case_hash(index));
    wasm.set(name, hash.toString(16).padStart(16, "0"));
    process.stdout.write(`${name} ${wasm.get(name)}\n`);
  } catch (error) {
    // A panic in wasm32 traps ("unreachable"): the native binary prints its message.
    problems.push(`${name}: the wasm32 run failed (${error.message}); run the native binary for the panic message`);
  }
}
const seconds = ((performance.now() - started) / 1000).toFixed(1);

if (native) {
  for (const [name, hash] of native) {
    if (!wasm.has(name)) {
      if (!problems.some((p) => p.startsWith(`${name}:`))) problems.push(`${name}: native only (not in the wasm32 module)`);
    } else if (wasm.get(name) !== hash) {
      problems.push(`${name}: native ${hash}, wasm32 ${wasm.get(name)}`);
    }
  }
  for (const name of wasm.keys()) {
    if (!native.has(name)) problems.push(`${name}: wasm32 only (not in the native list)`);
  }
}
if (problems.length > 0) {
  for (const problem of problems) process.stderr.write(`hashes: DIFFERS ${problem}\n`);
  fail(1, `${problems.length} of ${count} cases differ or failed (wasm32 runs took ${seconds} s)`);
}
const verdict = native ? ", each equal to the native hash bit for bit" : "";
process.stderr.write(`hashes: ${count} cases in wasm32 under V8 in ${seconds} s${verdict}\n`);
