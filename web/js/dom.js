// Small DOM helpers: $ (one element), h('p', {class: 'x'}, 'text', child) and svg(...) for SVG elements, and a
// form field's error (the element err-<field> beside it: the field is named by the API's dotted path). Text is
// always put in as text, never as HTML. An <img> of an /api picture is loaded with the server's token (api.js).

import { setImageSource } from './api.js';

export const $ = (selector, root = document) => root.querySelector(selector);

export function h(tag, attrs = {}, ...children) {
  const el = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs)) {
    if (value === undefined || value === null || value === false) continue;
    if (key === 'class') el.className = value;
    else if (key === 'text') el.textContent = value;
    else if (key.startsWith('on')) el.addEventListener(key.slice(2), value);
    else if (key === 'style') el.style.cssText = value;
    else if (key === 'src' && tag === 'img') setImageSource(el, String(value));
    else el.setAttribute(key, value === true ? '' : String(value));
  }
  for (const child of children.flat(Infinity)) {
    if (child === undefined || child === null || child === false) continue;
    el.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return el;
}

// A picture as a link to itself, which opens it at full size.
export function zoomable(src, alt) {
  return h('a', { href: src, target: '_blank', rel: 'noopener', class: 'zoom', title: 'Open the picture at full size' },
    h('img', { src, alt, loading: 'lazy' }));
}

const SVG_NS = 'http://www.w3.org/2000/svg';
export function svg(tag, attrs = {}, ...children) {
  const el = document.createElementNS(SVG_NS, tag);
  for (const [key, value] of Object.entries(attrs)) el.setAttribute(key, String(value));
  el.append(...children);
  return el;
}

export function fieldError(field) { return document.getElementById(`err-${field}`); }

export function showFieldError(field, message) {
  const err = fieldError(field);
  if (!err) return false;
  err.textContent = message;
  err.hidden = false;
  const wrapper = err.closest('.field');
  if (wrapper) wrapper.classList.add('invalid');
  const input = wrapper && wrapper.querySelector('input, select, textarea');
  if (input) input.setAttribute('aria-invalid', 'true');
  const details = err.closest('details');
  if (details) details.open = true;
  return true;
}

export function clearFieldError(field) {
  const err = fieldError(field);
  if (!err) return;
  err.hidden = true;
  err.textContent = '';
  const wrapper = err.closest('.field');
  if (wrapper) {
    wrapper.classList.remove('invalid');
    const input = wrapper.querySelector('input, select, textarea');
    if (input) input.removeAttribute('aria-invalid');
  }
}
