"use strict";
// The login page says why it came back: a wrong secret, or too many of them.
const why = { "#wrong": "Wrong secret.", "#wait": "Too many wrong secrets from here: wait a while and try again." };
document.getElementById("why").textContent = why[location.hash] || "";
