-- A study that never ends: tools/astest stops it at its time limit.
while true do end
