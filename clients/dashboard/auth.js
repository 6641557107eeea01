// The daemon's bearer token (kontaktd --token-file): asked for once per browser tab and kept
// in session storage, so it never appears in a URL, a log or the history.
const KEY = "kontaktd.token";

export function stored_token() {
  return sessionStorage.getItem(KEY);
}

export function forget_token() {
  sessionStorage.removeItem(KEY);
}

let pending = null;  // one prompt, however many requests were refused at once

/** Shows the token form; resolves once a token was entered. */
export function ask_for_token(message) {
  if (pending) return pending;
  pending = new Promise((resolve) => {
    const form = document.createElement("form");
    form.className = "token-form";
    form.innerHTML =
      '<label>This kontaktd needs an access token<input type="password" name="token" ' +
      'autocomplete="current-password" required></label><button type="submit">Sign in</button>' +
      '<p class="hint"></p>';
    form.querySelector(".hint").textContent = message;
    const overlay = document.createElement("div");
    overlay.className = "overlay";
    overlay.append(form);
    document.body.append(overlay);
    form.querySelector("input").focus();
    form.addEventListener("submit", (e) => {
      e.preventDefault();
      sessionStorage.setItem(KEY, form.elements.token.value.trim());
      overlay.remove();
      pending = null;
      resolve();
    });
  });
  return pending;
}
