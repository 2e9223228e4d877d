//! Prints every determinism case natively, one line each: its name, a space, and its hash
//! as 16 hexadecimal digits. `web/hashes.mjs` prints the same lines from the wasm32 build and
//! compares them with these.

fn main() {
    for case in determinism_check::cases() {
        println!("{} {:016x}", case.name, (case.hash)());
    }
}
