// Old URL of the grove page's module (pages cached before the reshape): the page is web/tree/grove_page.js.
import './tree/grove_page.js';
