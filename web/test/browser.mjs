// The browser test of the web build (bash web/build.sh first): serves target/web, opens it
// in Debian's Chromium as a phone (390 x 844 CSS pixels, device pixel ratio 2, touch) and
// checks, each against something the page does not report about itself:
//   1. the board: every brick of the seed's first board (from the native rules and layout,
//      `onemorebrick bricks`) shows its colour on the canvas where it belongs;
//   2. a touch drag aims and its release shoots: the game is saved at once with the volley,
//      and the balls fly (the canvas changes from one screenshot to the next);
//   3. a reload resumes the game from localStorage where it was when the page went (the
//      page-hide save), with the shot in it: a shot cannot be taken back by reloading;
//   4. a damaged saved game is reported on the screen, kept under another key as it was,
//      and a new game starts;
//   5. without ?seed two fresh visitors get different games (crypto.getRandomValues).
// Exit status 0 when all pass; each failure says what was expected.
import { fail, grab, changedPixels, decode, launch, native, newPage, PHONE, rgbAt, serve, status, until, untilStatus } from "./lib.mjs";

const SEED = 7;
const GAME_KEY = "onemorebrick/game.json";
const SETTINGS_KEY = "onemorebrick/settings.txt";
/** Largest difference per channel between a brick's colour and its pixel (8-bit rounding,
 * blending at the antialiased edges is not looked at). */
const COLOUR_TOLERANCE = 6;

function ok(message) {
    console.log(`ok: ${message}`);
}

const storage = (page, key) => page.evaluate((k) => window.localStorage.getItem(k), key);

/** Waits for the next frames after an input, so the game has read it. */
async function frames(page, count = 2) {
    const start = (await status(page)).frames;
    await untilStatus(page, `${count} more frames`, (s) => s.frames >= start + count);
}

async function checkBoard(page, what) {
    const { width, height } = PHONE.viewport;
    const dpr = PHONE.deviceScaleFactor;
    const bricks = native(["bricks", "--seed", String(SEED), "--width", String(width), "--height", String(height)])
        .trim().split("\n").map((line) => JSON.parse(line));
    if (bricks.length === 0) {
        fail("the native rules gave the first board no bricks");
    }
    // The board is drawn from the first frame on; a slide-in or a notice could cover it for a
    // moment, so poll until every brick shows.
    let wrong = [];
    const end = Date.now() + 30000;
    do {
        const image = await grab(page);
        if (image.width !== width * dpr || image.height !== height * dpr) {
            fail(`the screenshot is ${image.width}x${image.height}, not ${width * dpr}x${height * dpr}`);
        }
        wrong = bricks.map((b) => ({ ...b, got: rgbAt(image, b.x * dpr, b.y * dpr) }))
            .filter((b) => b.got.some((c, i) => Math.abs(c - b.rgb[i]) > COLOUR_TOLERANCE));
    } while (wrong.length > 0 && Date.now() < end);
    if (wrong.length > 0) {
        fail(`${what}: ${wrong.length} of ${bricks.length} bricks not shown, for example ${JSON.stringify(wrong.slice(0, 3))}`);
    }
    ok(`${what}: the ${bricks.length} bricks of seed ${SEED}'s first board are on the canvas in their colours`);
}

/** A touch drag from the board's middle up and to the left, released: the shot. */
async function dragToShoot(context, page) {
    const { width, height } = PHONE.viewport;
    const cdp = await context.newCDPSession(page);
    const at = (x, y) => [{ x: Math.round(x), y: Math.round(y), id: 1 }];
    await cdp.send("Input.dispatchTouchEvent", { type: "touchStart", touchPoints: at(width * 0.5, height * 0.55) });
    await frames(page);
    for (const t of [0.25, 0.5, 0.75, 1]) {
        await cdp.send("Input.dispatchTouchEvent", {
            type: "touchMove",
            touchPoints: at(width * (0.5 - 0.2 * t), height * (0.55 - 0.15 * t)),
        });
        await frames(page, 1);
    }
    await cdp.send("Input.dispatchTouchEvent", { type: "touchEnd", touchPoints: [] });
    await cdp.detach();
}

async function firstVisit(browser, url) {
    const { context, page } = await newPage(browser);
    await page.goto(`${url}?seed=${SEED}`);
    // A first game opens the help screen by itself; Escape closes it (and it is remembered).
    await untilStatus(page, "the help screen of a first game", (s) => s.view === "Help");
    await page.keyboard.press("Escape");
    await untilStatus(page, "the aiming view", (s) => s.view === "Aiming");
    const settings = await until("the settings saved", () => storage(page, SETTINGS_KEY));
    if (!settings.includes("help_seen = true")) {
        fail(`the settings in localStorage do not remember the help: ${JSON.stringify(settings)}`);
    }
    ok("a first visit shows the help once; closing it is saved in localStorage");
    await checkBoard(page, "first visit");
    return { context, page };
}

/**
 * Installed before the reload: on each load of the page, before its own scripts, keeps what
 * localStorage holds under the game's key (the save the game is about to load: the one the
 * page-hide save left) and, at the game's first published status (after its first frame),
 * that status and the saved game then. The game resumes a volley running, so later reads
 * could find it moved on (or the volley over and saved); these are exact.
 */
function watchLoads(key) {
    const probe = { loaded: window.localStorage.getItem(key), first: null, savedAtFirst: null };
    let current;
    window.onemorebrick = window.onemorebrick || {};
    Object.defineProperty(window.onemorebrick, "status", {
        enumerable: true,
        configurable: true,
        get: () => current,
        set: (value) => {
            if (probe.first === null) {
                probe.first = value;
                probe.savedAtFirst = window.localStorage.getItem(key);
            }
            current = value;
        },
    });
    window.onemorebrickTest = probe;
}

async function shootAndReload(context, page) {
    await page.addInitScript(watchLoads, GAME_KEY);
    const same = (x, y) => JSON.stringify(x) === JSON.stringify(y);
    for (let attempt = 1; ; attempt++) {
        if (attempt > 3) {
            fail("three volleys ended before the test could pause them and reload (each within a frame of the pause or the reload)");
        }
        // A notice (the reloaded page's "saved game resumed") takes the next key press.
        if ((await status(page)).notices.length > 0) {
            await page.keyboard.press("Escape");
            await untilStatus(page, "the notices put away", (s) => s.notices.length === 0);
        }
        const start = await status(page);
        await dragToShoot(context, page);
        const shot = await untilStatus(page, "the volley after the drag", (s) => s.commands > start.commands);
        // The save and the status in one go (no frame between): while this volley is live
        // the save must hold it.
        const read = await page.evaluate((key) => ({
            saved: JSON.parse(window.localStorage.getItem(key)),
            status: window.onemorebrick.status,
        }), GAME_KEY);
        let now = read.status;
        let a, b;
        if (now.phase === "volley") {
            if (read.saved.history.length !== shot.commands || read.saved.volley === null) {
                fail(`the shot was not saved with its volley: ${read.saved.history.length} commands, volley ${JSON.stringify(read.saved.volley)}`);
            }
            // The balls fly: the canvas changes between two screenshots of the volley
            // (decoded once the game is paused: the volley is short).
            a = await page.screenshot();
            await frames(page, 3);
            b = await page.screenshot();
            now = await status(page);
        }
        if (now.phase !== "volley") {
            console.log("the volley ended before the pause; shooting again");
            await untilStatus(page, "aiming again", (st) => st.view === "Aiming");
            continue;
        }
        await page.keyboard.press("Escape");
        const paused = await untilStatus(page, "the pause menu", (st) => st.view === "Paused");
        const [pa, pb] = [decode(a), decode(b)];
        const moved = changedPixels(pa, pb, { x: 0, y: 0, w: pa.width, h: pa.height });
        if (moved < 20 || now.balls < 1) {
            fail(`during the volley the canvas hardly changed (${moved} pixels, ${now.balls} balls)`);
        }
        ok(`a touch drag shot (level ${shot.level}): saved with the volley at once; ${now.balls} ball(s) in flight, ${moved} pixels changed`);
        if (paused.phase !== "volley") {
            console.log("the volley ended before the pause; shooting again");
            await page.keyboard.press("Escape");
            await untilStatus(page, "aiming again", (st) => st.view === "Aiming");
            continue;
        }
        const before = JSON.parse(await storage(page, GAME_KEY));
        // Reloading: the page-hide save keeps the volley's clock where it stood.
        await page.reload();
        const probe = await until("the reloaded game's first frame", () => page.evaluate(
            () => window.onemorebrickTest && window.onemorebrickTest.first ? window.onemorebrickTest : null,
        ));
        const loaded = JSON.parse(probe.loaded);
        if (loaded.seed !== before.seed || !same(loaded.history, before.history) || !same(loaded.state, before.state)) {
            fail("after the reload the saved game is not the one left (seed, commands, state differ)");
        }
        if (!loaded.volley || !same(loaded.volley.aim, before.volley.aim)) {
            fail(`after the reload the volley is gone or aimed elsewhere: ${JSON.stringify(loaded.volley)}`);
        }
        if (!(loaded.volley.elapsed > before.volley.elapsed)) {
            fail(`the page-hide save did not keep the volley's clock (${before.volley.elapsed} s at the shot, ${loaded.volley.elapsed} s after the reload)`);
        }
        const s = probe.first;
        if (s.phase !== "volley" && s.commands === paused.commands && s.seed === paused.seed && s.level > paused.level) {
            // The reloaded game plays the volley on from its first frame: it ended there.
            console.log(`the resumed volley ended in the reloaded page's first frame (paused at ${loaded.volley.elapsed.toFixed(3)} s); shooting again`);
            continue;
        }
        if (s.phase !== "volley" || s.commands !== paused.commands || s.level !== paused.level || s.score !== paused.score || s.seed !== paused.seed) {
            fail(`the reloaded game is not the one left: ${JSON.stringify(s)} after ${JSON.stringify(paused)}`);
        }
        // Its first save (at the start) wrote back the game it loaded, unchanged.
        if (!same(JSON.parse(probe.savedAtFirst), loaded)) {
            fail(`the reloaded game saved another game than the one it loaded: ${probe.savedAtFirst}`);
        }
        ok(`a reload resumed level ${s.level}, score ${s.score}, mid-volley at ${loaded.volley.elapsed.toFixed(3)} s (saved when the page went), the shot kept`);
        return;
    }
}

async function damagedSave(page) {
    const damaged = '{ "format": "onemorebrick-save", damaged by the browser test';
    await page.evaluate(([key, text]) => window.localStorage.setItem(key, text), [GAME_KEY, damaged]);
    await page.reload();
    const s = await untilStatus(page, "the report of the damaged save", (st) => st.notices.length > 0);
    if (!s.notices[0].includes("could not be loaded") || !s.notices.some((n) => n.includes(`${GAME_KEY}.bad-1`))) {
        fail(`the notices do not report the damaged save and where it went: ${JSON.stringify(s.notices)}`);
    }
    const kept = await storage(page, `${GAME_KEY}.bad-1`);
    if (kept !== damaged) {
        fail(`the damaged text was not kept as it was under ${GAME_KEY}.bad-1: ${JSON.stringify(kept)}`);
    }
    const fresh = JSON.parse(await storage(page, GAME_KEY));
    if (fresh.seed !== SEED || fresh.history.length !== 0) {
        fail("after the damaged save no new game was saved");
    }
    // On screen: the notice panel is drawn over the game, in colours of its own.
    const image = await grab(page);
    const dpr = PHONE.deviceScaleFactor;
    const [x, y, w, h] = s.notice_area || fail("no notice panel was drawn");
    const colours = new Set();
    for (let py = y * dpr + 2; py < (y + h) * dpr - 2; py += 3) {
        for (let px = x * dpr + 2; px < (x + w) * dpr - 2; px += 3) {
            colours.add(rgbAt(image, px, py).join(","));
        }
    }
    if (colours.size < 3) {
        fail(`the notice panel at ${s.notice_area} shows ${colours.size} colour(s): no text`);
    }
    ok(`a damaged save is reported on screen ("${s.notices[0].slice(0, 60)}..."), kept under ${GAME_KEY}.bad-1, a new game started`);
    // Any key puts the notices away.
    await page.keyboard.press("Escape");
    await untilStatus(page, "the notices put away", (st) => st.notices.length === 0 && st.view === "Aiming");
    await checkBoard(page, "the new game after the damaged save");
}

async function randomSeeds(browser, url) {
    const seeds = [];
    for (let i = 0; i < 2; i++) {
        const { context, page } = await newPage(browser);
        await page.goto(url);
        seeds.push((await untilStatus(page, "a fresh visitor's game", () => true)).seed);
        await context.close();
    }
    if (seeds[0] === seeds[1]) {
        fail(`two fresh visitors got the same seed ${seeds[0]}`);
    }
    ok(`two fresh visitors without ?seed got different games (seeds ${seeds[0]} and ${seeds[1]})`);
}

const server = await serve();
const browser = await launch();
try {
    const { context, page } = await firstVisit(browser, server.url);
    await shootAndReload(context, page);
    await damagedSave(page);
    await context.close();
    await randomSeeds(browser, server.url);
    console.log("browser test: all passed");
} finally {
    await browser.close();
    await server.close();
}
