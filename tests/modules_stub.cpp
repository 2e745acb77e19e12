void vmodules_anchor() {}
