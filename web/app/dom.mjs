// The page's elements the editor uses (index.html): the canvas and its 2-D
// context, and a lookup by id. Constant: no state here.
export const $ = (id) => document.getElementById(id);
export const canvas = $('canvas');
export const ctx = canvas.getContext('2d');
