// Loads the built package (crates/loci-wasm/pkg, from scripts/build-wasm.sh) as a plain ES
// module, giving init() the bytes of the .wasm (Node's fetch does not read files).
import { readFileSync } from "node:fs";
import { fileURLToPath } from "node:url";

const pkg = new URL("../pkg/", import.meta.url);
const loci = await import(new URL("web.js", pkg).href);
await loci.init(readFileSync(fileURLToPath(new URL("web/loci_wasm_bg.wasm", pkg))));
export default loci;

/** The text of a file of the repository's examples. */
export function example(path) {
  return readFileSync(fileURLToPath(new URL(`../../../examples/${path}`, import.meta.url)), "utf8");
}
