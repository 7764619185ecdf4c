// The crspline WebAssembly module, loaded once (dist/, next to app/).
import CrSpline from '../dist/crspline.mjs';

export const M = await CrSpline({ locateFile: (p) => new URL('../dist/' + p, import.meta.url).href });
