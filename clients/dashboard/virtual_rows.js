// A long table (thousands of increments) that stays fast: only the rows in view, plus a
// margin, exist in the DOM; spacer rows above and below keep the scroll height true. Rows
// have one height (measured on the first one drawn). It follows the end as rows arrive unless
// the reader scrolled up.
const OVERSCAN = 30;

export class VirtualRows {
  /**
   * @param box        the scrolling element around the table
   * @param tbody      the table's body
   * @param row_height px, a first guess until a row is measured
   * @param make_row   index -> <tr>
   */
  constructor(box, tbody, row_height, make_row) {
    this.box = box;
    this.tbody = tbody;
    this.row_height = row_height;
    this.make_row = make_row;
    this.count = 0;
    this.measured = false;
    this.shown = [-1, -1];
    this.top = document.createElement("tr");
    this.bottom = document.createElement("tr");
    this.top.className = this.bottom.className = "spacer";
    let pending = false;
    box.addEventListener("scroll", () => {
      if (pending) return;
      pending = true;
      requestAnimationFrame(() => {
        pending = false;
        this.render();
      });
    }, { passive: true });
  }

  /** There are now `count` rows (rows only ever get appended). */
  set_count(count) {
    if (count === this.count) return;
    const at_end = this.count === 0 || this.box.scrollTop + this.box.clientHeight >= this.box.scrollHeight - 4;
    this.count = count;
    this.tbody.parentElement.dataset.rows = String(count);
    this.shown = [-1, -1];  // the window may hold rows that did not exist yet
    this.render();
    if (at_end) this.box.scrollTop = this.box.scrollHeight;
  }

  render() {
    const first = Math.max(0, Math.floor(this.box.scrollTop / this.row_height) - OVERSCAN);
    const visible = Math.ceil((this.box.clientHeight || 400) / this.row_height);
    const last = Math.min(this.count, first + visible + 2 * OVERSCAN);
    if (first === this.shown[0] && last === this.shown[1]) return;
    this.shown = [first, last];
    this.top.style.height = `${first * this.row_height}px`;
    this.bottom.style.height = `${(this.count - last) * this.row_height}px`;
    const rows = [this.top];
    for (let i = first; i < last; i += 1) rows.push(this.make_row(i));
    rows.push(this.bottom);
    this.tbody.replaceChildren(...rows);
    if (!this.measured && last > first) {
      const height = rows[1].getBoundingClientRect().height;
      if (height > 0) {
        this.measured = true;
        if (Math.abs(height - this.row_height) > 0.01) {
          this.row_height = height;
          this.shown = [-1, -1];
          this.render();
        }
      }
    }
  }
}
