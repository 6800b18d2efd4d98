// The package for bundlers: the WebAssembly module is imported as an ES module (webpack,
// Vite, Rollup with a wasm plugin) and ready at import.
import * as raw from "./bundler/loci_wasm.js";
import { setBindings } from "./loci.js";

setBindings(raw);
export * from "./loci.js";
