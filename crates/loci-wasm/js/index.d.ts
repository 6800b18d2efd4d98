export * from "./loci.js";
