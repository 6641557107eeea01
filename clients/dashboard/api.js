// Calls to kontaktd's API with the session's token; a refused token asks for another and
// retries, so every page handles --token-file the same way.
import { ask_for_token, forget_token, stored_token } from "./auth.js";

export class ApiError extends Error {
  constructor(status, problem, url) {
    super(problem?.detail || `${url}: HTTP ${status}`);
    this.status = status;
    this.problem = problem;
  }
}

/** fetch() with the Authorization header; on 401 asks for the token and tries again. */
export async function api_fetch(url, options = {}) {
  for (;;) {
    const token = stored_token();
    const headers = { ...(options.headers || {}) };
    if (token) headers.Authorization = "Bearer " + token;
    const response = await fetch(url, { ...options, headers });
    if (response.status !== 401) return response;
    forget_token();
    await ask_for_token(token ? "The token was not accepted; enter another." : "Enter the token from the daemon's --token-file.");
  }
}

async function checked_json(url, response) {
  const body = response.status === 204 ? null : await response.json().catch(() => null);
  if (!response.ok) throw new ApiError(response.status, body, url);
  return body;
}

export async function get_json(url) {
  return checked_json(url, await api_fetch(url));
}

export async function post_json(url, body, headers = {}) {
  const options = { method: "POST", headers: { ...headers } };
  if (body !== undefined) {
    options.headers["Content-Type"] = "application/json";
    options.body = JSON.stringify(body);
  }
  return checked_json(url, await api_fetch(url, options));
}

/** Every row of a paged list: follows next_page_token until the end. */
export async function get_all_pages(url, rows_member) {
  const rows = [];
  let token = null;
  do {
    const sep = url.includes("?") ? "&" : "?";
    const page = await get_json(token ? `${url}${sep}page_token=${encodeURIComponent(token)}` : url);
    rows.push(...page[rows_member]);
    token = page.next_page_token;
  } while (token);
  return rows;
}

/**
 * Saves a result file when a token is in use: a plain link cannot carry the header, so the
 * file is fetched with it and handed over as a blob. (Without a token the link is followed.)
 */
export async function download_with_token(url, name) {
  const response = await api_fetch(url);
  if (!response.ok) throw new ApiError(response.status, null, url);
  const link = document.createElement("a");
  link.href = URL.createObjectURL(await response.blob());
  link.download = name;
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 60000);
}
