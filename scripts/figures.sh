#!/bin/sh
echo "figures: being written"
