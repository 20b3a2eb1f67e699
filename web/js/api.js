// The service's /api: JSON in and out, errors as ApiError with the problem+json details. Every request to /api
// goes through authorizedFetch: a server started with --token-file answers 401 without its token, so the page
// asks for the token once and keeps it for this tab (sessionStorage), sending it on every request.

class ApiError extends Error {
  constructor(status, detail, field, body = null) {
    super(detail);
    this.status = status;
    this.field = field || '';
    this.body = body;  // the answer's JSON document, when it had one
  }
}

const TOKEN_KEY = 'facetlight-token';
let asking = null;  // one prompt at a time, however many requests were refused together

function storedToken() {
  try {
    return sessionStorage.getItem(TOKEN_KEY) || '';
  } catch {
    return '';
  }
}

// Asks for the token after `refused` (the one just sent, or '') was turned down; '' when none is given.
function askForToken(refused) {
  if (storedToken() && storedToken() !== refused) return Promise.resolve(storedToken());  // given meanwhile
  asking ??= new Promise((resolve) => {
    if (refused) sessionStorage.removeItem(TOKEN_KEY);
    const given = (window.prompt(refused
      ? 'That token was refused. The access token of this facetlight server:'
      : 'This facetlight server asks for its access token (the first line of its --token-file):') || '').trim();
    if (given) sessionStorage.setItem(TOKEN_KEY, given);
    resolve(given);
  }).finally(() => { asking = null; });
  return asking;
}

function send(path, options, token) {
  const headers = { ...(options.headers || {}) };
  if (token) headers.Authorization = `Bearer ${token}`;
  return fetch(path, { ...options, headers });
}

// fetch() with the token; on a 401, asks for it (once) and sends the request again with it.
export async function authorizedFetch(path, options = {}) {
  const token = storedToken();
  const res = await send(path, options, token);
  if (res.status !== 401) return res;
  const given = await askForToken(token);
  return given ? send(path, options, given) : res;
}

// Whether `url` is one of this server's /api resources, which need the token.
export function isApiUrl(url) {
  try {
    const u = new URL(url, location.href);
    return u.origin === location.origin && u.pathname.startsWith('/api/');
  } catch {
    return false;
  }
}

// An /api picture or file fetched with the token, as an object URL (an <img> or a link cannot send it).
export async function authorizedObjectUrl(url) {
  const res = await authorizedFetch(url);
  if (!res.ok) throw new ApiError(res.status, `HTTP ${res.status}`);
  return URL.createObjectURL(await res.blob());
}

// Sets an <img>'s src: as it is while the server asks for no token, else through authorizedObjectUrl.
export function setImageSource(img, url) {
  if (!storedToken() || !isApiUrl(url)) {
    img.setAttribute('src', url);
    return;
  }
  authorizedObjectUrl(url).then((objectUrl) => {
    img.addEventListener('load', () => URL.revokeObjectURL(objectUrl), { once: true });
    img.setAttribute('src', objectUrl);
  }, () => img.setAttribute('src', url));
}

// Links to /api files (downloads, pictures opened in a new tab) are followed with the token once there is one.
export function followApiLinksWithToken() {
  document.addEventListener('click', async (event) => {
    const link = event.target.closest && event.target.closest('a[href]');
    if (!link || !storedToken() || !isApiUrl(link.href) || event.defaultPrevented || event.button !== 0) return;
    event.preventDefault();
    const opened = link.hasAttribute('download') ? null : window.open('', '_blank');
    try {
      const objectUrl = await authorizedObjectUrl(link.href);
      if (opened) {
        opened.location.href = objectUrl;
      } else {
        const save = document.createElement('a');
        save.href = objectUrl;
        save.download = link.getAttribute('download') || '';
        save.click();
        setTimeout(() => URL.revokeObjectURL(objectUrl), 60000);
      }
    } catch {
      if (opened) opened.close();
    }
  });
}

export async function api(path, options = {}) {
  let res;
  try {
    res = await authorizedFetch(path, { headers: { Accept: 'application/json' }, ...options });
  } catch {
    throw new ApiError(0, 'the service cannot be reached; is facetlight-server running?');
  }
  if (res.status === 204) return null;
  const type = res.headers.get('Content-Type') || '';
  const body = type.includes('json') ? await res.json().catch(() => null) : await res.text();
  if (!res.ok) {
    const detail = body && typeof body === 'object' ? body.detail || body.title : `HTTP ${res.status}`;
    const doc = body && typeof body === 'object' ? body : null;
    throw new ApiError(res.status, detail || `HTTP ${res.status}`, doc ? doc.field : '', doc);
  }
  return body;
}

export const jobUrl = (id, tail = '') => `/api/jobs/${encodeURIComponent(id)}${tail}`;
