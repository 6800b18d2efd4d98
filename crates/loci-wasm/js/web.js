// The package as a plain ES module (browsers without a bundler, Deno, Node): call init()
// once, with nothing (the .wasm beside this file is fetched), a URL, a Response, or the
// bytes of the .wasm.
import initRaw, * as raw from "./web/loci_wasm.js";
import { setBindings } from "./loci.js";

let ready = null;

export function init(input) {
  if (ready === null) {
    ready = initRaw(input === undefined ? undefined : { module_or_path: input }).then(() => {
      setBindings(raw);
    });
  }
  return ready;
}

export * from "./loci.js";
