// Peer driver: Shewchuk's Triangle (the npm package triangle-wasm, a WebAssembly build) on a .poly
// domain, written as OFF for meshcheck. Only for bench/compare; never part of the library.
// Usage: node triangle_wasm.js IN.poly OUT.off SWITCHES   (e.g. "pq30a0.001")
// Install: (cd bench/compare && npm install triangle-wasm)
const fs = require('fs');
const path = require('path');
const Triangle = require('triangle-wasm');

function readPoly(file) {
  const rows = fs.readFileSync(file, 'utf8').split('\n').map(l => l.split('#')[0].trim()).filter(l => l).map(l => l.split(/\s+/).map(Number));
  let i = 0;
  const [nv, , nattr, nmark] = rows[i++];
  const points = [], index = new Map();
  for (let k = 0; k < nv; ++k) { const r = rows[i++]; index.set(r[0], k); points.push(r[1], r[2]); }
  const [ns] = rows[i++];
  const segs = [];
  for (let k = 0; k < ns; ++k) { const r = rows[i++]; segs.push(index.get(r[1]), index.get(r[2])); }
  const [nh] = rows[i++] || [0];
  const holes = [];
  for (let k = 0; k < nh; ++k) { const r = rows[i++]; holes.push(r[1], r[2]); }
  return { pointlist: points, segmentlist: segs, holelist: holes };
}

const [inFile, outFile, switches] = process.argv.slice(2);
// Emscripten's loader would fetch() the .wasm by a plain path under Node 20: read it from disk instead.
delete globalThis.fetch;
Triangle.init(path.join(path.dirname(require.resolve('triangle-wasm')), 'triangle.out.wasm')).then(() => {
  const input = Triangle.makeIO(readPoly(inFile));
  const output = Triangle.makeIO();
  const t0 = process.hrtime.bigint();
  Triangle.triangulate(switches + 'zQ', input, output);
  const secs = Number(process.hrtime.bigint() - t0) / 1e9;
  const p = output.pointlist, t = output.trianglelist;
  const lines = ['OFF', `${p.length / 2} ${t.length / 3} 0`];
  for (let k = 0; k < p.length; k += 2) lines.push(`${p[k].toPrecision(17)} ${p[k + 1].toPrecision(17)} 0`);
  for (let k = 0; k < t.length; k += 3) lines.push(`3 ${t[k]} ${t[k + 1]} ${t[k + 2]}`);
  fs.writeFileSync(outFile, lines.join('\n') + '\n');
  console.log(JSON.stringify({ vertices: p.length / 2, triangles: t.length / 3, seconds: secs }));
  Triangle.freeIO(input, true);
  Triangle.freeIO(output);
});
