// Bundle the viewer and the studio page into birdsim/studio/static/ (committed, with
// PROVENANCE.json: versions from package-lock.json and a hash of the sources, so a test
// can tell a stale bundle). Run: npm ci && npm run build (or `make web`).
import { createHash } from "node:crypto";
import { readFileSync, readdirSync, writeFileSync } from "node:fs";
import { join } from "node:path";
import * as esbuild from "esbuild";

const out = new URL("../birdsim/studio/static/", import.meta.url).pathname;
for (const name of ["view", "studio"]) {
  await esbuild.build({
    entryPoints: [`src/${name}-entry.js`],
    bundle: true,
    minify: true,
    format: "iife",
    target: "es2020",
    legalComments: "eof",
    outfile: join(out, `${name}.js`),
    logLevel: "warning",
  });
}
const lock = JSON.parse(readFileSync("package-lock.json", "utf8"));
const pkgs = {};
for (const [path, info] of Object.entries(lock.packages)) {
  if (path.startsWith("node_modules/") && !path.slice(13).includes("node_modules/")) {
    pkgs[path.slice(13)] = { version: info.version, integrity: info.integrity };
  }
}
const h = createHash("sha256");
for (const f of ["package.json", "package-lock.json", "build.mjs", ...readdirSync("src").sort().map((f) => `src/${f}`)]) {
  h.update(f);
  h.update(readFileSync(f));
}
writeFileSync(
  join(out, "PROVENANCE.json"),
  JSON.stringify({ built_by: "web/build.mjs (esbuild, minified IIFE)", node: process.version, sources_sha256: h.digest("hex"), packages: pkgs }, null, 2) + "\n",
);
console.log(`wrote ${out}view.js, studio.js (+ .css) and PROVENANCE.json`);
