export * from "./loci.js";
/** Loads the WebAssembly module once: from the .wasm beside this file, a URL, a Response,
 * or its bytes. Every other call waits for it. */
export function init(
  input?: string | URL | Request | Response | BufferSource | WebAssembly.Module,
): Promise<void>;
