// The service's /api: JSON in and out, errors as ApiError with the problem+json details.

class ApiError extends Error {
  constructor(status, detail, field) {
    super(detail);
    this.status = status;
    this.field = field || '';
  }
}

export async function api(path, options = {}) {
  let res;
  try {
    res = await fetch(path, { headers: { Accept: 'application/json' }, ...options });
  } catch {
    throw new ApiError(0, 'the service cannot be reached; is facetlight-server running?');
  }
  if (res.status === 204) return null;
  const type = res.headers.get('Content-Type') || '';
  const body = type.includes('json') ? await res.json().catch(() => null) : await res.text();
  if (!res.ok) {
    const detail = body && typeof body === 'object' ? body.detail || body.title : `HTTP ${res.status}`;
    throw new ApiError(res.status, detail, body && typeof body === 'object' ? body.field : '');
  }
  return body;
}

export const jobUrl = (id, tail = '') => `/api/jobs/${encodeURIComponent(id)}${tail}`;
