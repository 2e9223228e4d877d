// The README's picture of the web build (bash web/build.sh first): the game on a phone
// (390 x 844 CSS pixels at pixel ratio 2) in headless Chromium, seed 7, after eight rounds
// shot by touch drags (sped up with F), aiming the next: written to docs/web.png (or the
// path given).
import { writeFileSync } from "node:fs";
import { join } from "node:path";

import { launch, newPage, PHONE, ROOT, serve, status, untilStatus } from "./lib.mjs";

const out = process.argv[2] || join(ROOT, "docs", "web.png");
const server = await serve();
const browser = await launch();
try {
    const { context, page } = await newPage(browser);
    await page.goto(`${server.url}?seed=7`);
    await untilStatus(page, "the help screen", (s) => s.view === "Help");
    await page.keyboard.press("Escape");
    await untilStatus(page, "aiming", (s) => s.view === "Aiming");
    const { width, height } = PHONE.viewport;
    const cdp = await context.newCDPSession(page);
    const point = (x, y) => [{ x: Math.round(x), y: Math.round(y), id: 1 }];
    const frames = async (n) => {
        const at = (await status(page)).frames;
        await untilStatus(page, "frames", (s) => s.frames >= at + n);
    };
    for (let round = 0; round < 8; round++) {
        const before = (await status(page)).commands;
        await cdp.send("Input.dispatchTouchEvent", { type: "touchStart", touchPoints: point(width * 0.5, height * 0.6) });
        await frames(2);
        const x = width * [0.15, 0.85, 0.3, 0.7, 0.05, 0.95, 0.4, 0.6][round];
        await cdp.send("Input.dispatchTouchEvent", { type: "touchMove", touchPoints: point(x, height * 0.3) });
        await frames(2);
        await cdp.send("Input.dispatchTouchEvent", { type: "touchEnd", touchPoints: [] });
        await untilStatus(page, "the shot", (s) => s.commands > before);
        for (let i = 0; i < 3; i++) {
            await page.keyboard.press("f");
        }
        await untilStatus(page, "the round's end", (s) => s.phase !== "volley", 300);
    }
    await frames(30);
    await cdp.send("Input.dispatchTouchEvent", { type: "touchStart", touchPoints: point(width * 0.5, height * 0.6) });
    const start = (await status(page)).frames;
    await untilStatus(page, "frames", (s) => s.frames > start + 1);
    await cdp.send("Input.dispatchTouchEvent", { type: "touchMove", touchPoints: point(width * 0.62, height * 0.35) });
    const moved = (await status(page)).frames;
    await untilStatus(page, "frames", (s) => s.frames > moved + 2);
    // Aiming, with the preview: the picture shows where the shot will go.
    writeFileSync(out, await page.screenshot());
    await cdp.send("Input.dispatchTouchEvent", { type: "touchEnd", touchPoints: [] });
    console.log(`wrote ${out} (${width * PHONE.deviceScaleFactor}x${height * PHONE.deviceScaleFactor})`);
    await context.close();
} finally {
    await browser.close();
    await server.close();
}
