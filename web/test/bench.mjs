// The web build's benchmarks, printed (bash web/build.sh first): the .wasm's size raw and
// gzipped; the time to the first frame (from the start of navigation to the end of the
// game's first frame, three fresh loads); and the frame with 1000 balls in flight
// (`?bench=frame`, the scene of `onemorebrick bench-frame`) in headless Chromium's software
// WebGL, at the desktop benchmark's 540 x 860 and on a phone's 390 x 844 at pixel ratio 2.
// With the native release build there (cargo build --release) and xvfb-run, the desktop's
// `bench-frame` runs too, for the figures side by side. Nothing is asserted.
import { spawnSync } from "node:child_process";
import { existsSync, readFileSync } from "node:fs";
import { join } from "node:path";
import { gzipSync } from "node:zlib";

import { fail, launch, newPage, PHONE, serve, until, WEB_DIR } from "./lib.mjs";

const wasm = readFileSync(join(WEB_DIR, "onemorebrick.wasm"));
const gz = gzipSync(wasm, { level: 9 }).length;
const kib = (n) => `${(n / 1024).toFixed(0)} KiB`;
console.log(`onemorebrick.wasm: ${wasm.length} bytes (${kib(wasm.length)}), gzipped -9: ${gz} bytes (${kib(gz)})`);

const server = await serve();
const browser = await launch();
const published = (page, key, seconds) => until(`window.onemorebrick.${key}`, () =>
    page.evaluate((k) => window.onemorebrick && window.onemorebrick[k], key), seconds);
try {
    const firsts = [];
    for (let i = 0; i < 3; i++) {
        const { context, page } = await newPage(browser);
        await page.goto(`${server.url}?seed=7`);
        firsts.push((await published(page, "first_frame", 120)).ms);
        await context.close();
    }
    const sorted = [...firsts].sort((a, b) => a - b);
    console.log(`time to first frame (navigation start to the end of the first frame, phone 390x844 @2): ${firsts.map((ms) => ms.toFixed(0)).join(", ")} ms; median ${sorted[1].toFixed(0)} ms`);

    const screens = [
        ["540x860 @1 (the desktop benchmark's window)", { viewport: { width: 540, height: 860 }, deviceScaleFactor: 1 }],
        ["390x844 @2 (a phone)", PHONE],
    ];
    for (const [name, options] of screens) {
        const { context, page } = await newPage(browser, options);
        await page.goto(`${server.url}?bench=frame`);
        const b = await published(page, "bench", 600);
        if (b.error) {
            fail(`the benchmark failed: ${b.error}`);
        }
        const p = b.physics;
        const d = b.drawing;
        console.log(`browser ${name}:`);
        console.log(`  physics: ${p.frames} frames of 1/60 s, ${p.balls.toFixed(0)} balls in flight on average: mean ${p.mean_ms.toFixed(3)} ms, worst ${p.worst_ms.toFixed(3)} ms per frame`);
        console.log(`  drawing: ${d.frames} frames, ${d.balls.toFixed(0)} balls on average: building the frame mean ${d.build_mean_ms.toFixed(3)} ms (worst ${d.build_worst_ms.toFixed(3)}); whole frame with rendering and present mean ${d.frame_mean_ms.toFixed(3)} ms (worst ${d.frame_worst_ms.toFixed(3)})`);
        await context.close();
    }
} finally {
    await browser.close();
    await server.close();
}

const release = join(WEB_DIR, "..", "release", "onemorebrick");
const xvfb = spawnSync("sh", ["-c", "command -v xvfb-run"]).status === 0;
if (existsSync(release) && xvfb) {
    const run = spawnSync("xvfb-run", ["-a", release, "bench-frame"], { encoding: "utf-8" });
    console.log("desktop (onemorebrick bench-frame, release, Mesa's llvmpipe under Xvfb, 540x860):");
    console.log(run.stdout.trim().split("\n").map((line) => `  ${line}`).join("\n"));
    if (run.status !== 0) {
        console.log(`  (exit ${run.status}: ${run.stderr.trim()})`);
    }
} else {
    console.log(`desktop: not run (needs ${release}: cargo build --release; and xvfb-run)`);
}
