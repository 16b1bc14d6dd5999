'use strict';
// The outside-solver protocol (docs/your-solver.md) for the engines' adapters: read the
// request directory, step an engine to every output time, write states.npy and result.txt.
// An adapter gives an `engine` (see run() below) and nothing else; every adapter shares the
// file formats, the step schedule, the presets and the timing written here, once.
const fs = require('fs');
const path = require('path');
const readline = require('readline');

// request.txt: one "key value..." line each; "option KEY VALUE" lines are the settings of a
// suite's [variant."ENGINE[NAME]"] table (protocol 2).
function readRequest(dir) {
  const request = { options: {} };
  for (const line of fs.readFileSync(path.join(dir, 'request.txt'), 'utf8').split('\n')) {
    const words = line.trim().split(/\s+/);
    if (!words[0]) continue;
    if (words[0] === 'option') request.options[words[1]] = words.slice(2).join(' ');
    else if (words[0] === 'output_times') request.output_times = words.slice(1).map(Number);
    else request[words[0]] = words.length === 2 && !isNaN(Number(words[1])) ? Number(words[1]) : words.slice(1).join(' ');
  }
  return request;
}

// An .npy file of little-endian float64 (NumPy's format 1.0): {shape, data}.
function readNpy(file) {
  const bytes = fs.readFileSync(file);
  const headerLength = bytes.readUInt16LE(8);
  const header = bytes.toString('latin1', 10, 10 + headerLength);
  if (!header.includes("'descr': '<f8'") || header.includes("'fortran_order': True"))
    throw new Error(`${file}: expected little-endian float64 in C order, header ${header}`);
  const shape = header.match(/'shape': \(([^)]*)\)/)[1].split(',').filter((s) => s.trim()).map(Number);
  const start = 10 + headerLength;
  const data = new Float64Array(bytes.buffer.slice(bytes.byteOffset + start, bytes.byteOffset + bytes.length));
  return { shape, data };
}

function writeNpy(file, shape, data) {
  let header = `{'descr': '<f8', 'fortran_order': False, 'shape': (${shape.join(', ')},), }`;
  header += ' '.repeat(63 - ((10 + header.length) % 64)) + '\n';  // the data starts 64-byte aligned
  const prefix = Buffer.alloc(10);
  prefix.write('\x93NUMPY', 0, 'latin1');
  prefix.writeUInt8(1, 6);
  prefix.writeUInt8(0, 7);
  prefix.writeUInt16LE(header.length, 8);
  fs.writeFileSync(file, Buffer.concat([prefix, Buffer.from(header, 'latin1'), Buffer.from(data.buffer)]));
}

// The disks of initial.npy: columns x, y, vx, vy, radius, mass, stone.
function readDisks(dir) {
  const { shape, data } = readNpy(path.join(dir, 'initial.npy'));
  const disks = [];
  for (let i = 0; i < shape[0]; ++i) {
    const r = data.subarray(7 * i, 7 * i + 7);
    disks.push({ x: r[0], y: r[1], vx: r[2], vy: r[3], radius: r[4], mass: r[5], stone: r[6] !== 0 });
  }
  return disks;
}

// The preset's settings with the request's options on top; an option the preset does not
// have, or a value of the wrong type, stops the call naming the key and what was expected.
function settings(engine, options) {
  const name = options.preset || 'tuned';
  const preset = engine.presets[name];
  if (!preset) throw new Error(`option preset = '${name}': expected one of ${Object.keys(engine.presets).join(', ')}`);
  const out = { ...preset, preset: name };
  for (const [key, text] of Object.entries(options)) {
    if (key === 'preset') continue;
    if (!(key in preset)) throw new Error(`option ${key}: unknown; expected one of ${Object.keys(preset).join(', ')}`);
    const kind = typeof preset[key];
    const value = kind === 'boolean' ? (text === 'true' ? true : text === 'false' ? false : undefined)
                : kind === 'number' ? Number(text) : text;
    if (value === undefined || (kind === 'number' && !Number.isFinite(value)))
      throw new Error(`option ${key} = '${text}': expected a ${kind}`);
    out[key] = value;
  }
  return out;
}

// The mean radius of the moving disks: engines with an absolute length scale are scaled by it.
function meanRadius(disks) {
  return disks.reduce((sum, d) => sum + d.radius, 0) / disks.length;
}

// The engines of engines.json: name, npm package, precision, a line about it.
function engineList() {
  return JSON.parse(fs.readFileSync(path.join(__dirname, 'engines.json'), 'utf8'));
}

// What engines.json says of engine `name`.
function engineEntry(name) {
  const entry = engineList().find((e) => e.name === name);
  if (!entry) throw new Error(`engines.json has no engine '${name}'`);
  return entry;
}

// The engine's npm package; when it is not installed, the call fails naming the engine and the
// command that installs it (the case then fails with that message, and the suite goes on).
function requireEngine(name) {
  const { package: pkg } = engineEntry(name);
  try {
    return require(pkg);
  } catch (e) {
    if (e.code !== 'MODULE_NOT_FOUND') throw e;
    process.stderr.write(`${name}: the npm package ${pkg} is not installed; run \`npm ci\` in ${__dirname} ` +
      '(scripts/install-deps.sh does)\n');
    process.exit(3);
  }
}

// The installed version (some packages do not export their package.json to require()), or ""
// when the package is not installed.
function packageVersion(name) {
  const manifest = path.join(__dirname, 'node_modules', name, 'package.json');
  return fs.existsSync(manifest) ? JSON.parse(fs.readFileSync(manifest, 'utf8')).version : '';
}

// The scene's features an engine may not have; "" when it has them all.
function refusal(request, engine) {
  if (request.boundary === 'periodic') return `${engine.name} has no periodic boundaries (a body cannot wrap around its world)`;
  return '';
}

// engine = { name, presets: {tuned, shipped}, init() (optional, async),
//            create(request, disks, settings) -> world }; its package and precision: engines.json
// world  = { step(h), state(i) -> [x, y, vx, vy], contacts (pair collisions so far),
//            free() (optional: what the engine does not give back to the garbage collector) }
// Steps of h = dt / substeps; output time t is reached after round(t / dt) steps of dt, as
// collide's own stepped backends do. `seconds` is the time spent in step() alone.
async function answer(engine, dir) {
  const request = readRequest(dir);
  const version = `${engine.packageName} ${packageVersion(engine.packageName)}`;
  const why = refusal(request, engine);
  if (why) {
    fs.writeFileSync(path.join(dir, 'result.txt'), `version ${version}\nrefuse ${why}\n`);
    return;
  }
  const disks = readDisks(dir);
  const chosen = settings(engine, request.options);
  if (engine.init) await (engine.ready = engine.ready || engine.init());  // once per process
  const world = engine.create(request, disks, chosen);
  try {
    const dt = request.dt, substeps = request.substeps || 1;
    let step = Math.round(request.start_time / dt), steps = 0, seconds = 0;
    const times = request.output_times;
    const states = new Float64Array(times.length * disks.length * 4);
    times.forEach((t, k) => {
      const target = Math.round(t / dt);
      const begin = process.hrtime.bigint();
      for (; step < target; ++step, ++steps)
        for (let s = 0; s < substeps; ++s) world.step(dt / substeps);
      seconds += Number(process.hrtime.bigint() - begin) * 1e-9;
      disks.forEach((d, i) => states.set(d.stone ? [d.x, d.y, 0, 0] : world.state(i), 4 * (k * disks.length + i)));
    });
    writeNpy(path.join(dir, 'states.npy'), [times.length, disks.length, 4], states);
    fs.writeFileSync(path.join(dir, 'result.txt'),
      `times ${times.join(' ')}\nsteps ${steps}\ncontacts ${world.contacts}\nseconds ${seconds}\n` +
      `precision ${engine.precision}\nversion ${version} (preset ${chosen.preset})\n`);
  } finally {
    if (world.free) world.free();
  }
}

// The long-lived mode (docs/your-solver.md, "A solver that serves many calls"): collide starts
// the adapter once as `node ENGINE.js --serve` and writes one request directory per line on its
// stdin; each is answered as a one-shot call would answer it, then "done" (or "failed REASON"
// when this request could not be answered) on stdout, which carries nothing else. End of file
// on stdin ends the process.
async function serve(engine) {
  console.log = console.error;  // an engine's own prints go to the log, never among the replies
  const requests = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
  for await (const dir of requests) {
    let reply = 'done';
    try {
      await answer(engine, dir);
    } catch (e) {
      process.stderr.write(`${engine.name}: ${e && e.stack ? e.stack : e}\n`);
      reply = `failed ${engine.name}: ${String(e && e.message ? e.message : e).replace(/\s+/g, ' ')}`;
    }
    process.stdout.write(`${reply}\n`);
  }
}

// Runs the adapter on the request directory named last on the command line, or serves request
// after request when that is `--serve`; a fault of a one-shot call is printed with the engine's
// name and the call fails.
function main(adapter) {
  const entry = engineEntry(adapter.name);
  const engine = { ...adapter, packageName: entry.package, precision: entry.precision };
  const last = process.argv[process.argv.length - 1];
  const done = last === '--serve' ? serve(engine) : answer(engine, last);
  done.catch((e) => {
    process.stderr.write(`${engine.name}: ${e && e.stack ? e.stack : e}\n`);
    process.exit(1);
  });
}

module.exports = { main, requireEngine, meanRadius, readNpy, writeNpy, readRequest, engineList, packageVersion };
