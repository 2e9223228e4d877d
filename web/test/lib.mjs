// Shared by the scripts that drive the web build in Debian's Chromium (browser.mjs, the
// test; bench.mjs, the benchmark; screenshot.mjs, the README's picture): a static server
// for target/web, the browser, polling, and reading pixels of page screenshots.
import { spawnSync } from "node:child_process";
import { existsSync, readFileSync, statSync } from "node:fs";
import { createServer } from "node:http";
import { extname, join, normalize, resolve } from "node:path";
import { fileURLToPath } from "node:url";

import { chromium } from "playwright-core";
import pngjs from "pngjs";

/** The repository's root. */
export const ROOT = resolve(fileURLToPath(new URL("../..", import.meta.url)));
const TARGET = process.env.CARGO_TARGET_DIR
    ? resolve(process.env.CARGO_TARGET_DIR)
    : join(ROOT, "target");
/** The web build's folder (web/build.sh writes it). */
export const WEB_DIR = process.env.WEB_OUT ? resolve(process.env.WEB_OUT) : join(TARGET, "web");
/** The native onemorebrick command (web/build.sh builds it, for the icons). */
export const NATIVE = join(TARGET, "debug", "onemorebrick");

/** A phone: 390 x 844 CSS pixels at a device pixel ratio of 2, with touch. */
export const PHONE = { viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, isMobile: true, hasTouch: true };

const TYPES = {
    ".html": "text/html; charset=utf-8",
    ".js": "text/javascript; charset=utf-8",
    ".wasm": "application/wasm",
    ".png": "image/png",
    ".webmanifest": "application/manifest+json",
};

/** Fails the script with `message` (exit 1). */
export function fail(message) {
    console.error(`FAIL: ${message}`);
    process.exit(1);
}

/** Serves WEB_DIR on 127.0.0.1 at a free port; resolves to { url, close }. */
export async function serve() {
    if (!existsSync(join(WEB_DIR, "index.html"))) {
        fail(`${WEB_DIR}/index.html not found: run bash web/build.sh first`);
    }
    const server = createServer((request, response) => {
        const path = decodeURIComponent(new URL(request.url, "http://x").pathname);
        const file = normalize(join(WEB_DIR, path === "/" ? "index.html" : path));
        if (!file.startsWith(WEB_DIR) || !existsSync(file) || !statSync(file).isFile()) {
            response.writeHead(404).end("not found");
            return;
        }
        const type = TYPES[extname(file)] || "application/octet-stream";
        response.writeHead(200, { "content-type": type, "cache-control": "no-store" });
        response.end(readFileSync(file));
    });
    await new Promise((ok) => server.listen(0, "127.0.0.1", ok));
    const url = `http://127.0.0.1:${server.address().port}/`;
    return { url, close: () => new Promise((ok) => server.close(ok)) };
}

/** Debian's Chromium (or $CHROMIUM), headless, its WebGL in software. */
export async function launch() {
    const executablePath = process.env.CHROMIUM || "/usr/bin/chromium";
    if (!existsSync(executablePath)) {
        fail(`${executablePath} not found: install Debian's chromium (or set CHROMIUM)`);
    }
    // Playwright gives every launch a fresh, temporary profile (its --user-data-dir).
    return chromium.launch({
        executablePath,
        headless: true,
        args: [
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--enable-unsafe-swiftshader",
            "--use-angle=swiftshader",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
        ],
    });
}

/** A new page in a new context (its own localStorage), reporting the page's errors. */
export async function newPage(browser, options = PHONE) {
    const context = await browser.newContext(options);
    const page = await context.newPage();
    page.on("pageerror", (error) => console.error(`page error: ${error.message}`));
    const seen = new Set();
    page.on("console", (message) => {
        // Each distinct error once (a repeated one would be every frame's).
        if (message.type() === "error" && !seen.has(message.text())) {
            seen.add(message.text());
            console.error(`page console: ${message.text()}`);
        }
    });
    return { context, page };
}

/**
 * Polls `check` (async, returning a truthy value when done) every 50 ms until it is done or
 * `seconds` have passed; resolves to its value, or fails naming `what`.
 */
export async function until(what, check, seconds = 60) {
    const end = Date.now() + seconds * 1000;
    let last;
    for (;;) {
        try {
            const value = await check();
            if (value) {
                return value;
            }
        } catch (error) {
            last = error;
        }
        if (Date.now() > end) {
            fail(`timed out after ${seconds} s waiting for ${what}${last ? ` (${last.message})` : ""}`);
        }
        await new Promise((ok) => setTimeout(ok, 50));
    }
}

/** The game's published state (`window.onemorebrick.status`), or undefined before a frame. */
export function status(page) {
    return page.evaluate(() => window.onemorebrick && window.onemorebrick.status);
}

/** Waits for the game's status to satisfy `predicate` (given the status); resolves to it. */
export function untilStatus(page, what, predicate, seconds = 60) {
    return until(what, async () => {
        const s = await status(page);
        return s && predicate(s) ? s : null;
    }, seconds);
}

/** A screenshot of the page as { width, height, data (RGBA) }, in device pixels. */
export async function grab(page) {
    return decode(await page.screenshot());
}

/** A PNG (a `page.screenshot()`) as { width, height, data (RGBA) }. */
export function decode(png) {
    return pngjs.PNG.sync.read(png);
}

/** The RGB at device pixel (x, y) of a screenshot: the median of its 3 x 3 block per channel. */
export function rgbAt(image, x, y) {
    const rgb = [[], [], []];
    for (let dy = -1; dy <= 1; dy++) {
        for (let dx = -1; dx <= 1; dx++) {
            const px = Math.min(image.width - 1, Math.max(0, Math.round(x) + dx));
            const py = Math.min(image.height - 1, Math.max(0, Math.round(y) + dy));
            const i = (py * image.width + px) * 4;
            for (let c = 0; c < 3; c++) {
                rgb[c].push(image.data[i + c]);
            }
        }
    }
    return rgb.map((values) => values.sort((a, b) => a - b)[4]);
}

/** How many pixels differ between two screenshots of the same size inside `rect` (device px). */
export function changedPixels(a, b, rect) {
    let changed = 0;
    for (let y = Math.floor(rect.y); y < rect.y + rect.h; y++) {
        for (let x = Math.floor(rect.x); x < rect.x + rect.w; x++) {
            const i = (y * a.width + x) * 4;
            if (a.data[i] !== b.data[i] || a.data[i + 1] !== b.data[i + 1] || a.data[i + 2] !== b.data[i + 2]) {
                changed++;
            }
        }
    }
    return changed;
}

/** Runs the native onemorebrick command with `args`; resolves to its standard output. */
export function native(args) {
    if (!existsSync(NATIVE)) {
        fail(`${NATIVE} not found: web/build.sh builds it (cargo build -p onemorebrick-app)`);
    }
    const run = spawnSync(NATIVE, args, { encoding: "utf-8" });
    if (run.status !== 0) {
        fail(`onemorebrick ${args.join(" ")}: ${run.stderr}`);
    }
    return run.stdout;
}
