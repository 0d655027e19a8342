# Sourced by run.sh and test.sh: installs the Rust pieces of the web build when they are missing (each step does
# nothing when already done). wasm-bindgen-cli must match the wasm-bindgen crate (=0.2.130) exactly.
rustup target add wasm32-unknown-unknown
if ! wasm-bindgen --version 2>/dev/null | grep -q '0\.2\.130'; then
  cargo install wasm-bindgen-cli --version 0.2.130
fi
