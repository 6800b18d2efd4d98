// The two Node APIs the example uses, declared here so that the check needs no @types/node.
declare module "node:fs" {
  export function readFileSync(path: string): Uint8Array;
}
declare module "node:module" {
  export function createRequire(url: string): { resolve(id: string): string };
}
