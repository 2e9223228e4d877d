// The page's side of crates/onemorebrick-web: a miniquad loader plugin. It adds the
// functions the wasm module imports (localStorage, crypto.getRandomValues, the URL query,
// performance.now, window.onemorebrick) and tells the game when the page is hidden.
//
// Text comes from the wasm module as a pointer and a length into its memory (UTF-8); an
// answer for it is kept here ("staged") until the module asks for its length and copies it
// into a buffer of its own. Each call returns a status: 0 done, 1 found (the answer is
// staged), 2 absent, 3 failed (the browser's message is staged).
"use strict";
(function () {
    const DONE = 0, FOUND = 1, ABSENT = 2, FAILED = 3;
    let staged = new Uint8Array(0);

    function text(ptr, len) {
        return new TextDecoder("utf-8").decode(new Uint8Array(wasm_memory.buffer, ptr, len));
    }

    function stage(value) {
        staged = new TextEncoder().encode(value);
    }

    function failed(error) {
        stage(String(error && error.message ? error.message : error));
        return FAILED;
    }

    // window.onemorebrick: what the game publishes for the scripts driving the page.
    window.onemorebrick = window.onemorebrick || {};

    function register_plugin(importObject) {
        const env = importObject.env;
        env.onemorebrick_storage_get = function (key_ptr, key_len) {
            try {
                const value = window.localStorage.getItem(text(key_ptr, key_len));
                if (value === null) {
                    return ABSENT;
                }
                stage(value);
                return FOUND;
            } catch (error) {
                return failed(error);
            }
        };
        env.onemorebrick_storage_set = function (key_ptr, key_len, value_ptr, value_len) {
            try {
                window.localStorage.setItem(text(key_ptr, key_len), text(value_ptr, value_len));
                return DONE;
            } catch (error) {
                return failed(error);
            }
        };
        env.onemorebrick_storage_remove = function (key_ptr, key_len) {
            try {
                window.localStorage.removeItem(text(key_ptr, key_len));
                return DONE;
            } catch (error) {
                return failed(error);
            }
        };
        env.onemorebrick_random_fill = function (ptr, len) {
            try {
                window.crypto.getRandomValues(new Uint8Array(wasm_memory.buffer, ptr, len));
                return DONE;
            } catch (error) {
                return failed(error);
            }
        };
        env.onemorebrick_query = function (name_ptr, name_len) {
            const value = new URLSearchParams(window.location.search).get(text(name_ptr, name_len));
            if (value === null) {
                return ABSENT;
            }
            stage(value);
            return FOUND;
        };
        env.onemorebrick_now = function () {
            return performance.now();
        };
        env.onemorebrick_publish = function (key_ptr, key_len, json_ptr, json_len) {
            window.onemorebrick[text(key_ptr, key_len)] = JSON.parse(text(json_ptr, json_len));
        };
        env.onemorebrick_staged_len = function () {
            return staged.length;
        };
        env.onemorebrick_staged_take = function (ptr, len) {
            new Uint8Array(wasm_memory.buffer, ptr, len).set(staged.subarray(0, len));
            staged = new Uint8Array(0);
        };
    }

    // The page going away or out of sight: the game saves now (no frame follows). Both
    // events, as browsers differ in which they send (a phone switching apps sends only
    // visibilitychange; some closes only pagehide); saving twice writes the same text.
    function hidden() {
        if (typeof wasm_exports !== "undefined" && wasm_exports.onemorebrick_web_page_hidden) {
            wasm_exports.onemorebrick_web_page_hidden();
        }
    }
    document.addEventListener("visibilitychange", function () {
        if (document.visibilityState === "hidden") {
            hidden();
        }
    });
    window.addEventListener("pagehide", hidden);

    miniquad_add_plugin({ register_plugin, version: 1, name: "onemorebrick_web" });
})();
